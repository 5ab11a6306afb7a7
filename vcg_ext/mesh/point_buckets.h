// Points bucketed on a grid of cubic cells, for "is there one near here" queries whose
// distance is at most a cell: each query looks at the 27 cells around its own.
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <map>
#include <vector>

namespace fcql {

class PointBuckets {
public:
  /// `points` must outlive the buckets, which hold indices into it; `cell` > 0.
  PointBuckets(const std::vector<Vec3>& points, double cell) : points_(points), cell_(cell) {}
  /// Buckets points[i].
  void add(int i) { cells_[cellOf(points_[i])].push_back(i); }
  void addAll() {
    for (int i = 0; i < int(points_.size()); ++i) add(i);
  }
  void clear() { cells_.clear(); }
  /// Distance from p to the nearest bucketed point within the 27 cells around p's own
  /// (infinity if none): exact for any point within a cell of p. The search stops at the first
  /// point found at `enough` or closer, whose distance it then returns.
  double nearest(const Vec3& p, double enough = 0) const;

private:
  std::array<long long, 3> cellOf(const Vec3& p) const;

  const std::vector<Vec3>& points_;
  double cell_;
  std::map<std::array<long long, 3>, std::vector<int>> cells_;
};

}  // namespace fcql
