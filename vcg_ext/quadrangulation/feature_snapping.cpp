#include "quadrangulation/feature_snapping.h"

#include "metrics/quad_quality.h"
#include "util/math_constants.h"

#include <algorithm>
#include <cmath>

namespace fcql {

namespace {

constexpr double kReach = 0.6;           ///< of the vertex's mean edge length
constexpr double kLeastRun = 3;          ///< a run of snappable segments shorter than this many quad edges is left
constexpr double kAlongDeg = 20;         ///< a quad edge at the vertex this close to the line's direction
constexpr double kKeepAbove = 0.1;       ///< a snap may not take a quad's scaled Jacobian to this or below

}  // namespace

int snapGridLinesToFeatures(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                            const std::vector<std::array<int, 3>>& featureSegments, const std::vector<char>& snappable,
                            const ClosestPointIndex& features, const std::vector<char>& movable,
                            const std::vector<std::vector<int>>& neighbours) {
  const int nv = quads.numVertices();
  if (featureSegments.empty() || nv == 0) return 0;
  const double cosAlong = std::cos(kAlongDeg * kPi / 180);
  // The length of the snappable run each segment belongs to: snappable segments joined where
  // exactly two feature segments meet.
  std::vector<int> degree(surfacePositions.size(), 0), firstAt(surfacePositions.size(), -1);
  for (const auto& s : featureSegments) ++degree[std::size_t(s[0])], ++degree[std::size_t(s[1])];
  std::vector<int> parent(featureSegments.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
  const auto root = [&](int i) {
    while (parent[std::size_t(i)] != i) i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
    return i;
  };
  for (std::size_t i = 0; i < featureSegments.size(); ++i) {
    if (!snappable[i]) continue;
    for (int k = 0; k < 2; ++k) {
      const std::size_t end = std::size_t(featureSegments[i][k]);
      if (degree[end] != 2) continue;
      if (firstAt[end] < 0) firstAt[end] = int(i);
      else parent[std::size_t(root(int(i)))] = root(firstAt[end]);
    }
  }
  std::vector<double> runLength(featureSegments.size(), 0);
  for (std::size_t i = 0; i < featureSegments.size(); ++i)
    if (snappable[i])
      runLength[std::size_t(root(int(i)))] +=
          (surfacePositions[std::size_t(featureSegments[i][1])] - surfacePositions[std::size_t(featureSegments[i][0])]).norm();
  std::vector<ClosestPoint> nearest(nv);
  std::vector<double> edge(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (!movable[v] || neighbours[v].empty()) continue;
    nearest[v] = features.closest(quads.positions[v]);
    for (int w : neighbours[v]) edge[v] += (quads.positions[w] - quads.positions[v]).norm();
    edge[v] /= double(neighbours[v].size());
  }
  std::vector<int> moved;
  std::vector<Vec3> was;
  for (int v = 0; v < nv; ++v) {
    if (!movable[v] || neighbours[v].empty() || !(edge[v] > 0)) continue;
    const ClosestPoint& cp = nearest[v];
    if (cp.triangle < 0 || cp.distance == 0 || cp.distance > kReach * edge[v] || !snappable[std::size_t(cp.triangle)] ||
        runLength[std::size_t(root(cp.triangle))] < kLeastRun * edge[v])
      continue;
    const auto& s = featureSegments[cp.triangle];
    const Vec3 along = (surfacePositions[s[1]] - surfacePositions[s[0]]).normalized();
    bool runsAlong = false, nearestLine = true;
    for (int w : neighbours[v]) {
      const Vec3 e = quads.positions[w] - quads.positions[v];
      if (e.norm() > 0 && std::abs(e.normalized().dot(along)) > cosAlong) {
        runsAlong = true;
        continue;
      }
      // A neighbour across the line's direction that is nearer it: its grid line goes there.
      const double dw = movable[w] ? nearest[w].distance : features.closest(quads.positions[w]).distance;
      if (dw < cp.distance) nearestLine = false;
    }
    if (!runsAlong || !nearestLine) continue;
    moved.push_back(v);
    was.push_back(quads.positions[v]);
  }
  if (moved.empty()) return 0;
  const QuadJacobian jacobian(quads);
  std::vector<int> around;
  jacobian.dependents(moved, around);
  std::vector<double> before, after;
  jacobian.values(around, before);
  for (std::size_t i = 0; i < moved.size(); ++i) quads.positions[moved[i]] = nearest[moved[i]].point;
  // Undo, a quad at a time, the snaps of the quads they spoil, until none is.
  std::vector<char> undone(moved.size(), 0);
  // Puts vertex v back if it was snapped and is not back yet; says whether it did.
  const auto undo = [&](int v) {
    const auto it = std::lower_bound(moved.begin(), moved.end(), v);
    if (it == moved.end() || *it != v) return false;
    const std::size_t i = std::size_t(it - moved.begin());
    if (undone[i]) return false;
    quads.positions[std::size_t(v)] = was[i], undone[i] = 1;
    return true;
  };
  const auto spoiled = [&](std::size_t k) { return before[k] > kKeepAbove && after[k] <= kKeepAbove; };
  for (bool changed = true; changed;) {
    changed = false;
    jacobian.values(around, after);
    for (std::size_t k = 0; k < around.size(); ++k)
      if (spoiled(k))
        for (int c : quads.quads[around[k]]) changed = undo(c) || changed;
    // A spoiled quad none of whose own corners moved (its normals turned by a neighbour's
    // snap): undo the snaps around its corners.
    for (std::size_t k = 0; k < around.size() && !changed; ++k)
      if (spoiled(k))
        for (int c : quads.quads[around[k]])
          for (int w : neighbours[c]) changed = undo(w) || changed;
  }
  return int(std::count(undone.begin(), undone.end(), 0));
}

}  // namespace fcql
