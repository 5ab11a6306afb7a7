// PointBuckets: a set of points bucketed on a uniform grid of one cell size, for "is any of
// them within r of p" questions (r at most the cell size) asked many times.
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <map>
#include <vector>

namespace fcql {

class PointBuckets {
public:
  /// `cell` > 0 is the grid's cell size and the largest radius nearest() answers for.
  PointBuckets(const std::vector<Vec3>& points, double cell);

  bool empty() const { return points_.empty(); }

  /// The distance from p to the nearest point, looked for within `cell` (infinity if none
  /// is), or the first distance found at most `enough` (the search then stops there: with
  /// millions of points, a caller that only needs "within enough" should not pay for more).
  double nearest(const Vec3& p, double enough = 0) const;

private:
  using Cell = std::array<long long, 3>;
  Cell cellOf(const Vec3& p) const;
  std::vector<Vec3> points_;
  double cell_;
  std::map<Cell, std::vector<int>> cells_;
};

}  // namespace fcql
