#include "quadrangulation/quad_smoothing.h"

#include "metrics/closest_point_index.h"
#include "metrics/quad_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

namespace fcql {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSnapShare = 0.35;
constexpr double kMinScaledJacobian = 0.1;

/// Per triangle and local edge (i → i+1): 1 if the edge is sharp (dihedral above the threshold).
std::vector<std::array<char, 3>> sharpEdges(const std::vector<Vec3>& P, const std::vector<std::array<int, 3>>& T,
                                            const std::vector<Vec3>& normals, double sharpAngleDeg) {
  std::vector<std::array<char, 3>> sharp(T.size(), {{0, 0, 0}});
  std::map<std::pair<int, int>, std::pair<int, int>> open;  // (min, max) → (triangle, edge)
  const double cosLimit = std::cos(sharpAngleDeg * kPi / 180);
  for (int t = 0; t < int(T.size()); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = T[t][i], b = T[t][(i + 1) % 3];
      const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
      auto it = open.find(key);
      if (it == open.end()) {
        open.emplace(key, std::make_pair(t, i));
        continue;
      }
      const int s = it->second.first, j = it->second.second;
      if (normals[t].dot(normals[s]) < cosLimit) sharp[t][i] = sharp[s][j] = 1;
      open.erase(it);
    }
  return sharp;
}

/// Per vertex, the quads that have it as a corner.
std::vector<std::vector<int>> quadsAroundVertices(const QuadMesh& quads) {
  std::vector<std::vector<int>> quadsOf(quads.numVertices());
  for (int q = 0; q < quads.numQuads(); ++q)
    for (int v : quads.quads[q]) quadsOf[v].push_back(q);
  return quadsOf;
}

/// Vertices of quads still folded or nearly flat (scaled Jacobian ≤ kMinScaledJacobian) try a
/// few positions and keep the one that most raises the worst scaled Jacobian of their quads:
/// the parallelogram completion a + c − b of each of their quads (a, c its neighbours there,
/// b the opposite corner), which makes that quad convex, and their neighbours' average, each
/// put back on the surface. A dart at a very obtuse patch corner is the usual case: the
/// Laplacian pulls its inner vertex towards the corner, the completion pushes it out.
void untangle(QuadMesh& quads, const ClosestPointIndex& surface, const std::vector<char>& fixed,
              const std::vector<std::vector<int>>& neighbours, SmoothingReport& report) {
  const std::vector<std::vector<int>> quadsOf = quadsAroundVertices(quads);
  auto worstAround = [&](int v) {
    double worst = 1;
    for (int q : quadsOf[v]) worst = std::min(worst, scaledJacobian(quads, q));
    return worst;
  };
  std::vector<Vec3> candidates;
  for (int sweep = 0; sweep < 10; ++sweep) {
    bool changed = false;
    for (int q = 0; q < quads.numQuads(); ++q) {
      if (scaledJacobian(quads, q) > kMinScaledJacobian) continue;
      for (int v : quads.quads[q]) {
        if (fixed[v] || neighbours[v].empty()) continue;
        const Vec3 original = quads.positions[v];
        candidates.clear();
        for (int r : quadsOf[v]) {
          const auto& f = quads.quads[r];
          const int i = int(std::find(f.begin(), f.end(), v) - f.begin());
          candidates.push_back(quads.positions[f[(i + 1) % 4]] + quads.positions[f[(i + 3) % 4]] -
                               quads.positions[f[(i + 2) % 4]]);
        }
        Vec3 average = Vec3::Zero();
        for (int w : neighbours[v]) average += quads.positions[w];
        candidates.push_back(average / double(neighbours[v].size()));
        double best = worstAround(v);
        Vec3 bestPosition = original;
        for (const Vec3& c : candidates) {
          quads.positions[v] = surface.closest(c).point;
          const double worst = worstAround(v);
          if (worst > best + 1e-9) best = worst, bestPosition = quads.positions[v];
        }
        quads.positions[v] = bestPosition;
        if (bestPosition != original) changed = true, ++report.untangledMoves;
      }
    }
    if (!changed) break;
  }
}

}  // namespace

SmoothingReport smoothQuadMesh(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                               const std::vector<std::array<int, 3>>& surfaceTriangles,
                               const SmoothingOptions& options) {
  if (options.iterations < 0) throw std::invalid_argument("smoothing: the number of iterations must be >= 0");
  if (!(options.step > 0 && options.step <= 1)) throw std::invalid_argument("smoothing: the step must be in (0, 1]");
  SmoothingReport report;
  if (options.iterations == 0 || quads.numQuads() == 0) return report;

  const ClosestPointIndex index(surfacePositions, surfaceTriangles);
  std::vector<Vec3> normals(surfaceTriangles.size(), Vec3::Zero());
  double longestEdge2 = 0;
  for (size_t t = 0; t < surfaceTriangles.size(); ++t) {
    const auto& f = surfaceTriangles[t];
    Vec3 n = (surfacePositions[f[1]] - surfacePositions[f[0]]).cross(surfacePositions[f[2]] - surfacePositions[f[0]]);
    if (n.norm() > 0) normals[t] = n.normalized();
    for (int i = 0; i < 3; ++i)
      longestEdge2 = std::max(longestEdge2, (surfacePositions[f[(i + 1) % 3]] - surfacePositions[f[i]]).squaredNorm());
  }
  const auto sharp = sharpEdges(surfacePositions, surfaceTriangles, normals, options.sharpAngleDeg);

  // Neighbours along quad edges; border vertices (an edge used by one quad) are fixed.
  const int nv = quads.numVertices();
  std::vector<std::vector<int>> neighbours(nv);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& q : quads.quads)
    for (int i = 0; i < 4; ++i) {
      const int a = q[i], b = q[(i + 1) % 4];
      directed[{a, b}] += 1;
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  std::vector<char> fixed(nv, 0);
  for (const auto& e : directed)
    if (!directed.count({e.first.second, e.first.first})) fixed[e.first.first] = fixed[e.first.second] = 1;
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  // Feature lines: the sharp edges as degenerate triangles (a, b, b), for snapping.
  std::vector<std::array<int, 3>> featureSegments;
  for (std::size_t t = 0; t < surfaceTriangles.size(); ++t)
    for (int i = 0; i < 3; ++i)
      if (sharp[t][i] && surfaceTriangles[t][i] < surfaceTriangles[t][(i + 1) % 3])
        featureSegments.push_back({surfaceTriangles[t][i], surfaceTriangles[t][(i + 1) % 3], surfaceTriangles[t][(i + 1) % 3]});
  std::unique_ptr<ClosestPointIndex> features;
  if (!featureSegments.empty()) features = std::make_unique<ClosestPointIndex>(surfacePositions, featureSegments);

  // Feature vertices: on (within a tiny tolerance of) a sharp edge; they stay.
  const double tolerance = 1e-7 * std::sqrt(longestEdge2) + 1e-12;
  for (int v = 0; v < nv && features; ++v) {
    if (fixed[v] || neighbours[v].empty()) continue;
    const ClosestPoint cp = features->closest(quads.positions[v]);
    const auto& e = featureSegments[cp.triangle];
    if (cp.distance <= std::max(tolerance, 1e-6 * (surfacePositions[e[1]] - surfacePositions[e[0]]).norm())) fixed[v] = 1;
  }
  for (int v = 0; v < nv; ++v) report.fixedVertices += fixed[v] || neighbours[v].empty();

  std::vector<Vec3> next(quads.positions);
  for (int it = 0; it < options.iterations; ++it) {
    const std::vector<Vec3> previous = quads.positions;
    std::vector<double> before(quads.numQuads());
    for (int q = 0; q < quads.numQuads(); ++q) before[q] = scaledJacobian(quads, q);
    for (int v = 0; v < nv; ++v) {
      next[v] = previous[v];
      if (fixed[v] || neighbours[v].empty()) continue;
      Vec3 average = Vec3::Zero();
      for (int w : neighbours[v]) average += previous[w];
      average /= double(neighbours[v].size());
      const ClosestPoint here = index.closest(previous[v]);
      const Vec3& n = normals[here.triangle];
      Vec3 move = (average - previous[v]) * options.step;
      move -= n * n.dot(move);
      next[v] = index.closest(previous[v] + move).point;
      if (features) {
        // A vertex close to a feature line (within kSnapShare of its mean edge length) goes
        // onto it, so the quads follow creases instead of cutting across them.
        double edge = 0;
        for (int w : neighbours[v]) edge += (previous[w] - previous[v]).norm();
        edge /= double(neighbours[v].size());
        const ClosestPoint onFeature = features->closest(next[v]);
        if (onFeature.distance < kSnapShare * edge) {
          next[v] = onFeature.point;
          ++report.snappedMoves;
        }
      }
    }
    quads.positions = next;
    // Undo the moves around any quad that this round folded or flattened (repeat: an undo can fold another).
    for (bool again = true; again;) {
      again = false;
      for (int q = 0; q < quads.numQuads(); ++q) {
        if (!(before[q] > kMinScaledJacobian) || scaledJacobian(quads, q) > kMinScaledJacobian) continue;
        for (int v : quads.quads[q])
          if (quads.positions[v] != previous[v]) {
            quads.positions[v] = previous[v];
            ++report.revertedMoves;
            again = true;
          }
      }
    }
  }
  untangle(quads, index, fixed, neighbours, report);
  return report;
}

int restoreSampledPositions(QuadMesh& quads, const std::vector<Vec3>& sampled, const std::vector<Vec3>& far,
                            double radius) {
  const int nv = quads.numVertices();
  if (int(sampled.size()) != nv) throw std::invalid_argument("restoreSampledPositions: one sampled position per vertex");
  if (far.empty() || !(radius > 0)) return 0;
  // Buckets of the far points on a grid of cell `radius`: each vertex looks at 27 cells.
  auto cellOf = [&](const Vec3& p) {
    return std::array<long long, 3>{{(long long)std::floor(p.x() / radius), (long long)std::floor(p.y() / radius),
                                     (long long)std::floor(p.z() / radius)}};
  };
  std::map<std::array<long long, 3>, std::vector<int>> cells;
  for (int i = 0; i < int(far.size()); ++i) cells[cellOf(far[i])].push_back(i);
  const std::vector<std::vector<int>> quadsOf = quadsAroundVertices(quads);
  std::vector<double> before(quads.numQuads());
  for (int q = 0; q < quads.numQuads(); ++q) before[q] = scaledJacobian(quads, q);
  // Vertex by vertex in index order: a return that folds or flattens one of the vertex's
  // quads (given where the others are by then) is not made.
  int count = 0;
  for (int v = 0; v < nv; ++v) {
    if (quadsOf[v].empty() || quads.positions[v] == sampled[v]) continue;
    const Vec3 smoothed = quads.positions[v];
    const auto c = cellOf(smoothed);
    double nearest = std::numeric_limits<double>::infinity();
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = cells.find({{c[0] + dx, c[1] + dy, c[2] + dz}});
          if (it == cells.end()) continue;
          for (int i : it->second) nearest = std::min(nearest, (far[i] - smoothed).norm());
        }
    if (!(nearest < radius)) continue;
    const double share = std::min(1.0, 2.0 * (1.0 - nearest / radius));
    quads.positions[v] = smoothed + (sampled[v] - smoothed) * share;
    bool folds = false;
    for (int q : quadsOf[v]) folds = folds || (before[q] > kMinScaledJacobian && scaledJacobian(quads, q) <= kMinScaledJacobian);
    if (folds) quads.positions[v] = smoothed;
    else ++count;
  }
  return count;
}

}  // namespace fcql
