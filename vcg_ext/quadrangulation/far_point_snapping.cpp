#include "quadrangulation/far_point_snapping.h"

#include "mesh/point_buckets.h"
#include "metrics/quad_quality.h"
#include "util/union_find.h"

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
                            double limit, double floor, std::vector<int>* pulled) {
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
  std::vector<char> isPulled(pulled ? quads.positions.size() : 0, 0);
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
      if (border[v] || jacobian.quadsAround(v).empty() || (pulled && isPulled[v])) continue;
      jacobian.dependents(v, around);
      jacobian.values(around, before);
      const Vec3 was = quads.positions[v];
      quads.positions[v] = p;
      jacobian.values(around, after);
      const bool spoils = spoilsQuads(before, after, floor);
      // The quads' edges at v stay near the surface: v does not bridge over to another part of
      // it (across a gap narrower than a quad).
      bool bridges = false;
      for (int q : jacobian.quadsAround(v)) {
        const auto& f = quads.quads[q];
        const int k = int(std::find(f.begin(), f.end(), v) - f.begin());
        for (int w : {f[(k + 1) % 4], f[(k + 3) % 4]})
          bridges = bridges || surface.closest((p + quads.positions[w]) / 2).distance > limit;
      }
      // Pulling, the nearest corner that does not bridge goes, spoiling or not: a farther one
      // would stretch its quads across the spike's foot.
      if (bridges || (spoils && !pulled)) {
        quads.positions[v] = was;
        continue;
      }
      if (spoils) isPulled[v] = 1, pulled->push_back(v);
      taken.add(i);
      ++moved;
      break;
    }
  }
  return moved;
}

int pullVerticesToFarPoints(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                            const std::vector<std::array<int, 3>>& surfaceTriangles, const ClosestPointIndex& surface,
                            const std::vector<Vec3>& far, double limit, double floor, SmoothingOptions smoothing,
                            int rings) {
  const std::vector<Vec3> was = quads.positions;
  std::vector<double> before, after;
  QuadJacobian(quads).all(before);
  std::vector<int> pulled;
  const int moved = snapVerticesToFarPoints(quads, surface, far, limit, floor, &pulled);
  if (pulled.empty()) return moved;
  const std::vector<Vec3> onPoints = quads.positions;  // the vertices moved onto far points there
  const std::size_t nv = quads.positions.size();
  std::vector<char> region(nv, 0);
  for (int v : pulled) region[v] = 1;
  growAcrossQuads(quads, region, rings);
  smoothing.frozen.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) smoothing.frozen[v] = region[v] ? 0 : 1;
  for (int v : pulled) smoothing.frozen[v] = 1;
  smoothQuadMesh(quads, surfacePositions, surfaceTriangles, smoothing);
  // The parts of the region apart (two more rings: a quad's figure depends on the quads around
  // its corners): each is undone if it folds a quad that was not folded.
  std::vector<char> reach = region;
  growAcrossQuads(quads, reach, 2);
  UnionFind parts{int(nv)};
  for (const auto& q : quads.quads)
    for (int i = 1; i < 4; ++i)
      if (reach[q[0]] && reach[q[i]]) parts.unite(q[0], q[i]);
  QuadJacobian(quads).all(after);
  std::vector<char> folds(nv, 0);  // per part (at its root): a quad folded that was not
  for (int q = 0; q < quads.numQuads(); ++q) {
    const int v = quads.quads[q][0];
    if (reach[v] && before[q] > 0 && !(after[q] > 0)) folds[parts.find(v)] = 1;
  }
  int left = 0;  // vertices still on the far points they went onto
  for (std::size_t v = 0; v < nv; ++v) {
    if (reach[v] && folds[parts.find(int(v))]) quads.positions[v] = was[v];
    if (onPoints[v] != was[v] && quads.positions[v] == onPoints[v]) ++left;
  }
  return left;
}

}  // namespace fcql
