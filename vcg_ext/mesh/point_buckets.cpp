#include "mesh/point_buckets.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fcql {

std::array<long long, 3> PointBuckets::cellOf(const Vec3& p) const {
  return {{(long long)std::floor(p.x() / cell_), (long long)std::floor(p.y() / cell_),
           (long long)std::floor(p.z() / cell_)}};
}

double PointBuckets::nearest(const Vec3& p, double enough) const {
  const auto c = cellOf(p);
  double best = std::numeric_limits<double>::infinity();
  for (long long dx : {0, -1, 1})
    for (long long dy : {0, -1, 1})
      for (long long dz : {0, -1, 1}) {
        const auto it = cells_.find({{c[0] + dx, c[1] + dy, c[2] + dz}});
        if (it == cells_.end()) continue;
        for (int i : it->second) {
          best = std::min(best, (points_[i] - p).norm());
          if (best <= enough) return best;
        }
      }
  return best;
}

}  // namespace fcql
