#include "quadrangulation/far_point_snapping.h"

#include "mesh/point_buckets.h"
#include "metrics/quad_quality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace fcql {

namespace {

/// At most this many spots, or this share of the quads' vertices, get a vertex each.
constexpr double kFewSpots = 16;
constexpr double kSpotShare = 0.01;

}  // namespace

int snapVerticesToFarPoints(QuadMesh& quads, const ClosestPointIndex& surface, const std::vector<Vec3>& far,
                            double limit, double floor) {
  if (far.empty() || quads.numQuads() == 0 || !(limit > 0)) return 0;
  const ClosestPointIndex quadIndex(quads.positions, quadTriangles(quads));
  // The points of the surface the quads miss, farthest first.
  std::vector<std::pair<double, int>> missed;
  for (int i = 0; i < int(far.size()); ++i) {
    if (!(surface.closest(far[i]).distance <= 1e-6 * limit)) continue;
    const double d = quadIndex.closest(far[i]).distance;
    if (d > limit) missed.emplace_back(d, i);
  }
  if (missed.empty()) return 0;
  std::sort(missed.begin(), missed.end(), [](const auto& a, const auto& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  // The points taken, bucketed in cells as large as the largest distance (the farthest a
  // point looks for one taken before).
  PointBuckets taken(far, missed.front().first);
  // The spots: the points left once those near one before are dropped. Where they are many,
  // the quads miss the surface widely, not at a few tips (quads far coarser than its curves,
  // or a bound finer than its detail), and only smaller quads help: nothing is moved.
  std::size_t spots = 0;
  for (const auto& [distance, i] : missed)
    if (!(taken.nearest(far[i]) < distance)) ++spots, taken.add(i);
  if (double(spots) > std::max(kFewSpots, kSpotShare * double(quads.numVertices()))) return 0;
  taken.clear();  // from here on, the points a vertex went onto
  // Border vertices stay where they are.
  const std::vector<char> border = quadBorderVertices(quads);
  const QuadJacobian jacobian(quads);
  std::vector<int> around;
  std::vector<double> before, after;
  int moved = 0;
  for (const auto& [distance, i] : missed) {
    const Vec3& p = far[i];
    if (taken.nearest(p) < distance) continue;
    std::array<int, 3> corners = quadIndex.triangle(quadIndex.closest(p).triangle);
    std::sort(corners.begin(), corners.end(), [&](int a, int b) {
      const double da = (quads.positions[a] - p).squaredNorm(), db = (quads.positions[b] - p).squaredNorm();
      return da < db || (da == db && a < b);
    });
    for (int v : corners) {
      if (border[v] || jacobian.quadsAround(v).empty()) continue;
      jacobian.dependents(v, around);
      jacobian.values(around, before);
      const Vec3 was = quads.positions[v];
      quads.positions[v] = p;
      jacobian.values(around, after);
      bool spoils = spoilsQuads(before, after, floor);
      // The quads' edges at v stay near the surface: v does not bridge over to another part of
      // it (across a gap narrower than a quad).
      for (int q : jacobian.quadsAround(v)) {
        const auto& f = quads.quads[q];
        const int k = int(std::find(f.begin(), f.end(), v) - f.begin());
        for (int w : {f[(k + 1) % 4], f[(k + 3) % 4]})
          spoils = spoils || surface.closest((p + quads.positions[w]) / 2).distance > limit;
      }
      if (spoils) {
        quads.positions[v] = was;
        continue;
      }
      taken.add(i);
      ++moved;
      break;
    }
  }
  return moved;
}

}  // namespace fcql
