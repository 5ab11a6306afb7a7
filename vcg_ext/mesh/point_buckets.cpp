#include "mesh/point_buckets.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fcql {

PointBuckets::PointBuckets(const std::vector<Vec3>& points, double cell) : points_(points), cell_(cell) {
  if (!(cell > 0) || !std::isfinite(cell)) throw std::invalid_argument("PointBuckets: the cell size must be positive");
  for (int i = 0; i < int(points_.size()); ++i) cells_[cellOf(points_[i])].push_back(i);
}

PointBuckets::Cell PointBuckets::cellOf(const Vec3& p) const {
  return {{(long long)std::floor(p.x() / cell_), (long long)std::floor(p.y() / cell_),
           (long long)std::floor(p.z() / cell_)}};
}

double PointBuckets::nearest(const Vec3& p, double enough) const {
  double best = std::numeric_limits<double>::infinity();
  const Cell c = cellOf(p);
  // The 27 cells around p's hold every point within one cell size of it.
  for (long long dx : {0, -1, 1})
    for (long long dy : {0, -1, 1})
      for (long long dz : {0, -1, 1}) {
        auto it = cells_.find({{c[0] + dx, c[1] + dy, c[2] + dz}});
        if (it == cells_.end()) continue;
        for (int i : it->second) {
          best = std::min(best, (points_[i] - p).norm());
          if (best <= enough) return best;
        }
      }
  return best <= cell_ ? best : std::numeric_limits<double>::infinity();
}

}  // namespace fcql
