#include "quadrangulation/far_point_snapping.h"

#include "metrics/quad_quality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <cstdint>
#include <unordered_map>
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
  // Border vertices (on an edge of one quad) stay where they are.
  std::unordered_map<std::uint64_t, int> edgeUses;
  auto key = [](int a, int b) { return (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b)); };
  for (const auto& q : quads.quads)
    for (int i = 0; i < 4; ++i) ++edgeUses[key(q[i], q[(i + 1) % 4])];
  std::vector<char> border(quads.positions.size(), 0);
  for (const auto& q : quads.quads)
    for (int i = 0; i < 4; ++i)
      if (edgeUses[key(q[i], q[(i + 1) % 4])] == 1) border[q[i]] = border[q[(i + 1) % 4]] = 1;
  const QuadJacobian jacobian(quads);
  std::vector<int> around;
  std::vector<double> before, after;
  // The points taken, bucketed on a grid of cells as large as the largest distance (the farthest
  // a point looks for one taken before): each point looks at the 27 cells around its own.
  const double cell = missed.front().first;
  auto cellOf = [&](const Vec3& p) {
    return std::array<long long, 3>{{(long long)std::floor(p.x() / cell), (long long)std::floor(p.y() / cell),
                                     (long long)std::floor(p.z() / cell)}};
  };
  std::map<std::array<long long, 3>, std::vector<Vec3>> taken;
  auto nearTaken = [&](const Vec3& p, double distance) {
    const auto c = cellOf(p);
    for (long long dx : {-1, 0, 1})
      for (long long dy : {-1, 0, 1})
        for (long long dz : {-1, 0, 1}) {
          const auto it = taken.find({{c[0] + dx, c[1] + dy, c[2] + dz}});
          if (it != taken.end())
            for (const Vec3& t : it->second)
              if ((t - p).norm() < distance) return true;
        }
    return false;
  };
  // The spots: the points left once those near one before are dropped. Where they are many,
  // the quads miss the surface widely, not at a few tips (quads far coarser than its curves,
  // or a bound finer than its detail), and only smaller quads help: nothing is moved.
  std::size_t spots = 0;
  for (const auto& [distance, i] : missed)
    if (!nearTaken(far[i], distance)) ++spots, taken[cellOf(far[i])].push_back(far[i]);
  if (double(spots) > std::max(kFewSpots, kSpotShare * double(quads.numVertices()))) return 0;
  taken.clear();  // from here on, the points a vertex went onto
  int moved = 0;
  for (const auto& [distance, i] : missed) {
    const Vec3& p = far[i];
    if (nearTaken(p, distance)) continue;
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
      bool spoils = false;
      for (std::size_t k = 0; k < around.size() && !spoils; ++k)
        spoils = (before[k] > floor && after[k] <= floor) || (before[k] > 0 && after[k] <= 0);
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
      taken[cellOf(p)].push_back(p);
      ++moved;
      break;
    }
  }
  return moved;
}

}  // namespace fcql
