#include "quadrangulation/quad_smoothing.h"

#include "quadrangulation/feature_snapping.h"

#include "quadrangulation/field_relaxation.h"
#include "quadrangulation/fold_repair.h"

#include "mesh/closest_point_index.h"
#include "mesh/point_buckets.h"
#include "util/worker_threads.h"
#include "metrics/quad_quality.h"
#include "util/math_constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

namespace fcql {

namespace {

constexpr double kSnapShare = 0.35;
constexpr double kMinScaledJacobian = 0.1;
/// How far around a poor quad the smoothing moves vertices when it keeps the sampled grid
/// elsewhere (SmoothingOptions::keepGridAbove).
constexpr int kKeepGridRings = 2;
constexpr double kUntangleFloor = 0.02;  ///< the untangling may take a good quad this low, not lower
constexpr double kSlideAngleDeg = 60;
constexpr double kSlideTurnDeg = 20;
/// Vertices nearer than this many of their mean edge lengths to a feature line stay out of the
/// relaxation towards the field.
constexpr double kRelaxFeatureGap = 2;
constexpr char kFixed = 1;               ///< a border vertex, or one at a corner of the feature lines
constexpr char kOnFeature = 2;           ///< on a feature line: smoothing keeps it, untangling slides it along

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

/// Vertices of quads still folded or nearly flat (scaled Jacobian ≤ kMinScaledJacobian) try a
/// few positions and keep the one that most lowers the shortfall below that threshold of the
/// quads that depend on them (theirs and their neighbours'), among the positions where none of
/// those quads falls below its figure or the threshold, whichever is lower: the parallelogram completion a + c − b of each
/// of their quads (a, c its neighbours there, b the opposite corner), which makes that quad
/// convex, their neighbours' average and the centre of their quads, each also half-way from
/// where the vertex is, put back on the surface. A dart at a very obtuse patch corner is the
/// usual case: the Laplacian pulls its inner vertex towards the corner, the completion pushes it
/// out. So no move folds a quad that was not folded, or worsens one that was.
void untangle(QuadMesh& quads, const ClosestPointIndex& surface, const ClosestPointIndex* features,
              const std::vector<char>& slidable, const std::vector<char>& fixed, const std::vector<std::vector<int>>& neighbours, const QuadJacobian& jacobian,
              SmoothingReport& report, bool snapToFeatures) {
  // Where vertex v may go for target c: the surface's closest point, or for a vertex on a
  // straight crease (kOnFeature) the crease's, so that it slides along it and stays on it.
  // It stays where it is rather than go onto another, unslidable, feature line.
  auto place = [&](int v, const Vec3& c) {
    if (fixed[v] != kOnFeature) return surface.closest(c).point;
    const ClosestPoint onFeature = features->closest(c);
    return slidable[onFeature.triangle] ? onFeature.point : quads.positions[v];
  };
  // Feature vertices move only as corners of a quad folded at the start of the sweep: sliding
  // along a crease can uncover a sharp tip, so it is kept for where nothing else helps.
  std::vector<char> foldedCorner(quads.positions.size(), 0);
  auto movable = [&](int v) {
    return (!fixed[v] || (features && fixed[v] == kOnFeature && foldedCorner[v])) && !neighbours[v].empty();
  };
  std::vector<int> around;
  std::vector<double> before;
  std::vector<double> now;
  // How bad a quad is: its shortfall below the threshold, ten times more below 0 (folded).
  auto penalty = [](double j) { return std::max(0.0, kMinScaledJacobian - j) + 10 * std::max(0.0, -j); };
  // The quads around at the vertex's current position: their summed penalty, or infinity when
  // one that was not folded falls to kUntangleFloor or below its figure before, whichever is
  // lower, or one that was folded gets worse. Quads may get a little worse than the threshold
  // while their neighbours unfold, but none folds.
  auto shortfall = [&] {
    jacobian.values(around, now);
    double sum = 0;
    for (std::size_t i = 0; i < around.size(); ++i) {
      const double floor = before[i] > 0 ? std::min(before[i], kUntangleFloor) : before[i];
      if (now[i] < floor) return std::numeric_limits<double>::infinity();
      sum += penalty(now[i]);
    }
    return sum;
  };
  std::vector<Vec3> candidates;
  std::vector<int> bad, corners;
  double lastTotal = 0;
  // A vertex tried without moving is tried again only once a vertex its quads' figures depend
  // on (the corners of the quads around the corners of its dependents, which give their
  // normals) has moved: the same positions give the same search, so skipping it changes
  // nothing. Clock ticks count the moves.
  std::vector<long> movedAt(quads.positions.size(), 0), stillAt(quads.positions.size(), -1);
  long clock = 0;
  auto unchangedSince = [&](long t) {
    for (int r : around)
      for (int c : quads.quads[r])
        for (int s : jacobian.quadsAround(c))
          for (int w : quads.quads[s])
            if (movedAt[w] > t) return false;
    return true;
  };
  for (int sweep = 0; sweep < 20; ++sweep) {
    bad.clear();
    jacobian.all(now);
    double total = 0;
    std::fill(foldedCorner.begin(), foldedCorner.end(), 0);
    for (int q = 0; q < quads.numQuads(); ++q) {
      if (now[q] <= kMinScaledJacobian) bad.push_back(q), total += kMinScaledJacobian - now[q];
      if (now[q] <= 0)
        for (int v : quads.quads[q]) foldedCorner[v] = 1;
    }
    // Stop once a sweep gains less than 1% of the shortfall.
    if (sweep > 0 && total > lastTotal * 0.99) break;
    lastTotal = total;
    if (bad.empty()) break;
    // The corners of the bad quads first, then their neighbours (a fold can need room).
    corners.clear();
    for (int q : bad)
      for (int v : quads.quads[q]) corners.push_back(v);
    const std::size_t first = corners.size();
    for (std::size_t i = 0; i < first; ++i)
      for (int w : neighbours[corners[i]]) corners.push_back(w);
    std::sort(corners.begin() + first, corners.end());
    corners.erase(std::unique(corners.begin() + first, corners.end()), corners.end());
    bool changed = false;
    // One vertex moves at a time: the normals it changes are updated as it moves (moved()).
    jacobian.track();
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const int v = corners[i];
      if (!movable(v)) continue;
      jacobian.dependents(v, around);
      if (stillAt[v] >= 0 && unchangedSince(stillAt[v])) continue;
      const Vec3 original = quads.positions[v];
      jacobian.values(around, before);
      double best = 0;
      for (double j : before) best += penalty(j);
      if (!(best > 0)) continue;
      candidates.clear();
      Vec3 centre = Vec3::Zero();
      for (int r : jacobian.quadsAround(v)) {
        const auto& f = quads.quads[r];
        const int k = int(std::find(f.begin(), f.end(), v) - f.begin());
        candidates.push_back(quads.positions[f[(k + 1) % 4]] + quads.positions[f[(k + 3) % 4]] -
                             quads.positions[f[(k + 2) % 4]]);
        for (int w : f) centre += quads.positions[w];
      }
      candidates.push_back(centre / (4.0 * double(jacobian.quadsAround(v).size())));
      Vec3 average = Vec3::Zero();
      for (int w : neighbours[v]) average += quads.positions[w];
      candidates.push_back(average / double(neighbours[v].size()));
      // A vertex near a feature line may belong on it (a grid line next to a crease).
      if (features && snapToFeatures) candidates.push_back(features->closest(original).point);
      const std::size_t whole = candidates.size();
      for (std::size_t c = 0; c < whole; ++c) candidates.push_back((candidates[c] + original) / 2);
      Vec3 bestPosition = original;
      for (const Vec3& c : candidates) {
        quads.positions[v] = place(v, c);
        jacobian.moved(v);
        const double s = shortfall();
        if (s < best - 1e-9) best = s, bestPosition = quads.positions[v];
      }
      // Then a pattern search in the tangent plane from the best position: 8 directions, the
      // step halved from half the mean edge whenever none of them helps.
      double edge = 0;
      for (int w : neighbours[v]) edge += (quads.positions[w] - original).norm();
      edge /= double(neighbours[v].size());
      for (double r = 0.5 * edge; r > 0.02 * edge;) {
        quads.positions[v] = bestPosition;
        jacobian.moved(v);
        const Vec3 n = jacobian.vertexNormal(v);
        if (n.isZero() || !(best > 0)) break;
        const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
        const Vec3 from = bestPosition;
        for (int k = 0; k < 8; ++k) {
          const double a = k * kPi / 4;
          quads.positions[v] = place(v, from + (t1 * std::cos(a) + t2 * std::sin(a)) * r);
          jacobian.moved(v);
          const double s = shortfall();
          if (s < best - 1e-9) best = s, bestPosition = quads.positions[v];
        }
        if (bestPosition == from) r /= 2;
      }
      quads.positions[v] = bestPosition;
      jacobian.moved(v);
      if (bestPosition != original) changed = true, ++report.untangledMoves, movedAt[v] = ++clock, stillAt[v] = -1;
      else stillAt[v] = clock;
    }
    jacobian.untrack();
    if (!changed) break;
  }
  // Folds left in clusters (a patch's grid folded over itself) need several vertices to move
  // together: the free vertices within a few rings of them are smoothed as a region (plain
  // averaging with reprojection, the region's rim fixed, which unfolds a disk like Tutte's
  // embedding), and the result is kept when it leaves fewer folded quads and folds none that
  // was not, else undone. Growing regions: 2, 4 and 8 rings.
  for (int rings : {2, 4, 8}) {
    std::vector<char> inRegion(quads.positions.size(), 0);
    std::vector<int> frontier;
    jacobian.all(now);
    for (int q = 0; q < quads.numQuads(); ++q)
      if (now[q] <= 0)
        for (int v : quads.quads[q])
          if (!inRegion[v]) inRegion[v] = 1, frontier.push_back(v);
    if (frontier.empty()) break;
    for (int ring = 0; ring < rings; ++ring) {
      std::vector<int> grown;
      for (int v : frontier)
        for (int w : neighbours[v])
          if (!inRegion[w]) inRegion[w] = 1, grown.push_back(w);
      frontier.swap(grown);
    }
    // Connected parts of the region's free vertices, each tried on its own.
    std::vector<int> part(quads.positions.size(), -1);
    for (int seed = 0; seed < int(quads.positions.size()); ++seed) {
      if (!inRegion[seed] || fixed[seed] || part[seed] >= 0 || neighbours[seed].empty()) continue;
      std::vector<int> members{seed};
      part[seed] = seed;
      for (std::size_t i = 0; i < members.size(); ++i)
        for (int w : neighbours[members[i]])
          if (inRegion[w] && !fixed[w] && part[w] < 0) part[w] = seed, members.push_back(w);
      std::vector<int> affected;
      jacobian.dependents(members, affected);
      jacobian.values(affected, before);
      int foldedBefore = 0;
      for (double j : before) foldedBefore += j <= 0;
      if (foldedBefore == 0) continue;
      std::vector<Vec3> saved;
      for (int v : members) saved.push_back(quads.positions[v]);
      for (int it = 0; it < 30; ++it)
        for (int v : members) {
          Vec3 average = Vec3::Zero();
          for (int w : neighbours[v]) average += quads.positions[w];
          quads.positions[v] = surface.closest(average / double(neighbours[v].size())).point;
        }
      int foldedAfter = 0;
      bool newFold = false;
      jacobian.values(affected, now);
      for (std::size_t i = 0; i < affected.size(); ++i) {
        const double j = now[i];
        foldedAfter += j <= 0;
        newFold = newFold || (j <= 0 && before[i] > 0);
      }
      if (foldedAfter < foldedBefore && !newFold) {
        report.untangledMoves += int(members.size());
      } else {
        for (std::size_t i = 0; i < members.size(); ++i) quads.positions[members[i]] = saved[i];
      }
    }
  }
}

/// Per vertex the sum (and number) of its corners in the rectangles aligned with the field that
/// best fit its quads: centred at the quad's centre, sides along the cross directions closest to
/// the quad's own two directions (midpoints of opposite edges), extents the quad's along them.
/// The field and normal of a quad are those of the surface triangle nearest to its centre.
/// Quads whose corners are all `frozen` (SmoothingOptions::frozen, may be empty) are skipped.
void alignedTargets(const QuadMesh& quads, const ClosestPointIndex& index, const std::vector<Vec3>& normals,
                    const std::vector<Vec3>& directions, const std::vector<char>& frozen, int threads,
                    std::vector<Vec3>& sum, std::vector<int>& count) {
  std::fill(sum.begin(), sum.end(), Vec3::Zero());
  std::fill(count.begin(), count.end(), 0);
  const auto& P = quads.positions;
  auto centreOf = [&](const std::array<int, 4>& f) { return Vec3((P[f[0]] + P[f[1]] + P[f[2]] + P[f[3]]) / 4); };
  // The nearest triangles on the worker threads, the sums in order.
  std::vector<int> nearest(quads.quads.size(), -1);
  auto allFixed = [&](const std::array<int, 4>& f) {
    return !frozen.empty() && frozen[f[0]] && frozen[f[1]] && frozen[f[2]] && frozen[f[3]];
  };
  runOnWorkerThreads(threads, [&](int w) {
    for (std::size_t q = std::size_t(w); q < quads.quads.size(); q += std::size_t(threads))
      if (!allFixed(quads.quads[q])) nearest[q] = index.closest(centreOf(quads.quads[q])).triangle;
  });
  for (std::size_t q = 0; q < quads.quads.size(); ++q) {
    const auto& f = quads.quads[q];
    const Vec3 centre = centreOf(f);
    const int t = nearest[q];
    if (t < 0) continue;
    const Vec3& n = normals[t];
    Vec3 d = directions[t] - n * n.dot(directions[t]);
    if (!(d.norm() > 0) || n.isZero()) continue;
    d.normalize();
    const Vec3 eu = (P[f[1]] + P[f[2]] - P[f[0]] - P[f[3]]) / 2, ev = (P[f[2]] + P[f[3]] - P[f[0]] - P[f[1]]) / 2;
    // The quarter turn of the cross closest to eu; the other axis is n × it.
    Vec3 d1 = d;
    double best = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k, d = n.cross(d))
      if (d.dot(eu) > best) best = d.dot(eu), d1 = d;
    const Vec3 d2 = n.cross(d1);
    const double a = eu.dot(d1) / 2, b = ev.dot(d2) / 2;
    if (!(a > 0) || !(b > 0)) continue;  // turned too far from the field to be fitted
    const std::array<Vec3, 4> corner{centre - a * d1 - b * d2, centre + a * d1 - b * d2, centre + a * d1 + b * d2,
                                     centre - a * d1 + b * d2};
    for (int k = 0; k < 4; ++k) sum[f[k]] += corner[k], ++count[f[k]];
  }
}

/// The vertices a smoothing round moves: all, unless `keepGridAbove` > 0 and the quads follow
/// the field (`alignedCount`: per vertex, its quads fitted to the field): then only those
/// within kKeepGridRings rings of a quad whose scaled Jacobian (`jacobianOf`) is below
/// `keepGridAbove`, or with a quad around them that has no field (a mean-value patch; not
/// asked of `frozen` vertices, whose quads alignedTargets may skip).
std::vector<char> movingVertices(const QuadMesh& quads, const QuadJacobian& jacobian, const std::vector<double>& jacobianOf,
                                 const std::vector<std::vector<int>>& neighbours, const std::vector<int>& alignedCount,
                                 const std::vector<char>& frozen, double keepGridAbove) {
  const int nv = quads.numVertices();
  std::vector<char> moving(nv, 1);
  if (!(keepGridAbove > 0) || alignedCount.size() != std::size_t(nv)) return moving;
  for (int v = 0; v < nv; ++v)
    moving[v] = (frozen.empty() || !frozen[v]) && alignedCount[v] < int(jacobian.quadsAround(v).size());
  for (int q = 0; q < quads.numQuads(); ++q)
    if (jacobianOf[q] < keepGridAbove)
      for (int c : quads.quads[q]) moving[c] = 1;
  for (int ring = 0; ring < kKeepGridRings; ++ring) {
    std::vector<char> grown = moving;
    for (int v = 0; v < nv; ++v)
      if (moving[v])
        for (int w : neighbours[v]) grown[w] = 1;
    moving.swap(grown);
  }
  return moving;
}

/// The relaxation towards the field (field_relaxation.h), `options.fieldRelaxationRounds`
/// times. Vertices within kRelaxFeatureGap of their mean edge length from a feature line stay
/// (moved beside a crease, the quads cut it: the camelhead's ridges then missed the distance
/// bound). Each round's moves go through `keepFromFolding`; the moves it undid are tried again
/// half and a quarter of the way, through it again. (A floor above the smoothing's 0.1 for the
/// relaxation alone kept the least scaled Jacobians of aqua_center and fertility, 0.55 and
/// 0.49, above 0.3, but left the dragon 11–12 folded quads at half the size instead of 8.)
template <class KeepFromFolding>
void relaxRounds(QuadMesh& quads, const ClosestPointIndex& index, const std::vector<Vec3>& normals,
                 const SmoothingOptions& options, const std::vector<char>& fixed,
                 const std::vector<std::vector<int>>& neighbours, const ClosestPointIndex* features,
                 const QuadJacobian& jacobian, KeepFromFolding&& keepFromFolding, std::vector<double>& before,
                 SmoothingReport& report) {
  const int nv = quads.numVertices();
  std::vector<char> movable(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (fixed[v] || neighbours[v].empty()) continue;
    movable[v] = 1;
    if (!features) continue;
    double edge = 0;
    for (int w : neighbours[v]) edge += (quads.positions[w] - quads.positions[v]).norm();
    edge /= double(neighbours[v].size());
    if (features->closest(quads.positions[v]).distance < kRelaxFeatureGap * edge) movable[v] = 0;
  }
  // keepFromFolding compares with `before`: the scaled Jacobians where the moves start.
  for (int round = 0; round < options.fieldRelaxationRounds; ++round) {
    const FieldRelaxation relaxed =
        relaxTowardsField(quads, index, normals, options.triangleDirections, movable, options.fieldRelaxationAnchor);
    if (!relaxed.solved) break;
    const std::vector<Vec3> previous = quads.positions;
    jacobian.all(before);
    quads.positions = relaxed.positions;
    keepFromFolding(previous);
    for (double share : {0.5, 0.25}) {
      const std::vector<Vec3> kept = quads.positions;
      jacobian.all(before);
      bool any = false;
      for (int v = 0; v < nv; ++v)
        if (kept[v] == previous[v] && relaxed.positions[v] != previous[v]) {
          quads.positions[v] = index.closest(previous[v] + (relaxed.positions[v] - previous[v]) * share).point;
          any = true;
        }
      if (!any) break;
      keepFromFolding(kept);
    }
    for (int v = 0; v < nv; ++v) report.relaxedMoves += quads.positions[v] != previous[v];
  }
}

/// smoothQuadMesh on the whole of `quads` (its frozen vertices kept where they are).
SmoothingReport smoothWhole(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                            const std::vector<std::array<int, 3>>& surfaceTriangles, const SmoothingOptions& options) {
  if (options.iterations < 0) throw std::invalid_argument("smoothing: the number of iterations must be >= 0");
  if (!(options.step > 0 && options.step <= 1)) throw std::invalid_argument("smoothing: the step must be in (0, 1]");
  if (!(options.keepGridAbove >= 0 && options.keepGridAbove <= 1))
    throw std::invalid_argument("smoothing: keepGridAbove must be in [0, 1]");
  if (options.fieldRelaxationRounds < 0) throw std::invalid_argument("smoothing: the relaxation rounds must be >= 0");
  if (!(options.fieldRelaxationAnchor > 0)) throw std::invalid_argument("smoothing: the relaxation's anchor must be positive");
  if (!options.frozen.empty() && options.frozen.size() != quads.positions.size())
    throw std::invalid_argument("smoothing: one frozen flag per vertex, or none");
  SmoothingReport report;
  if (options.iterations == 0 || quads.numQuads() == 0) return report;

  const ClosestPointIndex index(surfacePositions, surfaceTriangles);
  const int threads = workerThreadCount(options.threads, quads.numVertices() / 2000 + 1);
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
  for (const auto& q : quads.quads)
    for (int i = 0; i < 4; ++i) {
      const int a = q[i], b = q[(i + 1) % 4];
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  std::vector<char> fixed = quadBorderVertices(quads);
  for (char& f : fixed) f = f ? kFixed : 0;
  const std::vector<char> onBorder = fixed;
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
  std::vector<int> sharpDegree(surfacePositions.size(), 0);
  for (const auto& e : featureSegments) ++sharpDegree[e[0]], ++sharpDegree[e[1]];
  // Creases sharp enough to slide along (dihedral above kSlideAngleDeg): those of a CAD model,
  // not the short zigzag ridges of a scan, along which a vertex would leave the ridge.
  std::vector<char> slidable(featureSegments.size(), 0);
  {
    std::map<std::pair<int, int>, int> firstTriangle;
    std::map<std::pair<int, int>, double> cosine;
    for (int t = 0; t < int(surfaceTriangles.size()); ++t)
      for (int i = 0; i < 3; ++i) {
        const int a = surfaceTriangles[t][i], b = surfaceTriangles[t][(i + 1) % 3];
        if (!sharp[t][i]) continue;
        const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
        auto it = firstTriangle.find(key);
        if (it == firstTriangle.end()) firstTriangle.emplace(key, t);
        else cosine[key] = normals[t].dot(normals[it->second]);
      }
    // And straight: at each end that continues the line (two sharp edges there), the next
    // segment turns by less than kSlideTurnDeg.
    std::vector<Vec3> direction(surfacePositions.size(), Vec3::Zero());
    std::vector<double> turnCosine(surfacePositions.size(), 1);
    for (const auto& e : featureSegments) {
      const Vec3 d = (surfacePositions[e[1]] - surfacePositions[e[0]]).normalized();
      for (int k = 0; k < 2; ++k) {
        const int end = e[k];
        const Vec3 out = k == 0 ? d : Vec3(-d);  // leaving the end
        if (direction[end].isZero()) direction[end] = out;
        else turnCosine[end] = -direction[end].dot(out);
      }
    }
    const double cosSlide = std::cos(kSlideAngleDeg * kPi / 180), cosTurn = std::cos(kSlideTurnDeg * kPi / 180);
    for (std::size_t i = 0; i < featureSegments.size(); ++i) {
      auto it = cosine.find({featureSegments[i][0], featureSegments[i][1]});
      slidable[i] = it != cosine.end() && it->second < cosSlide;
      for (int k = 0; k < 2; ++k) {
        const int end = featureSegments[i][k];
        if (sharpDegree[end] == 2 && turnCosine[end] < cosTurn) slidable[i] = 0;
      }
    }
  }
  std::unique_ptr<ClosestPointIndex> features;
  if (!featureSegments.empty()) features = std::make_unique<ClosestPointIndex>(surfacePositions, featureSegments);
  // Grid lines sampled beside a straight sharp crease (a layout side traced along it) go onto
  // it first (feature_snapping.h): the smoothing below moves only where quads are poor.
  if (features) {
    std::vector<char> movable(nv, 0);
    for (int v = 0; v < nv; ++v)
      movable[v] = !fixed[v] && !neighbours[v].empty() && (options.frozen.empty() || !options.frozen[v]);
    report.snappedMoves += snapGridLinesToFeatures(quads, surfacePositions, featureSegments, slidable, *features, movable, neighbours);
  }

  // How repairFolds may move each vertex: inner ones on the surface, feature vertices along
  // their lines (not where lines meet), border vertices not at all.
  std::vector<char> repairMoves(nv, kOnSurface);
  for (int v = 0; v < nv; ++v)
    if (fixed[v] || neighbours[v].empty()) repairMoves[v] = kStays;
  // Feature vertices: on (within a tiny tolerance of) a sharp edge; they stay.
  const double tolerance = 1e-7 * std::sqrt(longestEdge2) + 1e-12;
  for (int v = 0; v < nv && features; ++v) {
    if (fixed[v] || neighbours[v].empty()) continue;
    const ClosestPoint cp = features->closest(quads.positions[v]);
    const auto& e = featureSegments[cp.triangle];
    const double near = std::max(tolerance, 1e-6 * (surfacePositions[e[1]] - surfacePositions[e[0]]).norm());
    if (cp.distance > near) continue;
    // On a feature line; at one of its ends or corners (not two sharp edges at that surface
    // vertex) it stays put for good.
    fixed[v] = slidable[cp.triangle] ? kOnFeature : kFixed;
    repairMoves[v] = kAlongFeature;
    for (int end : {e[0], e[1]}) {
      if (sharpDegree[end] == 2 || (surfacePositions[end] - cp.point).norm() > near) continue;
      fixed[v] = kFixed;
      if (sharpDegree[end] > 2) repairMoves[v] = kStays;  // where lines meet; at a line's loose end it may slide
    }
  }
  for (int v = 0; v < nv; ++v) report.fixedVertices += fixed[v] || neighbours[v].empty();
  // Frozen vertices stay as border vertices do (counted above only if they are fixed anyway).
  for (int v = 0; v < nv && !options.frozen.empty(); ++v)
    if (options.frozen[v]) fixed[v] = kFixed, repairMoves[v] = kStays;

  // A round moves every free vertex at once; then every quad that the round took from above
  // kMinScaledJacobian to it or below (folded, turned against the surface or nearly flat, at
  // any of its four corners) has the moves undone that it depends on (its corners' and their
  // neighbours': the surface normal at a corner comes from the quads around it), until none is
  // left. So no step folds or flattens a quad; quads already bad are left to the untangling.
  const QuadJacobian jacobian(quads);
  std::vector<Vec3> next(quads.positions);
  std::vector<double> before(quads.numQuads()), after;
  const bool aligned = options.triangleDirections.size() == surfaceTriangles.size() && !surfaceTriangles.empty();
  std::vector<Vec3> alignedSum(aligned ? nv : 0);
  std::vector<int> alignedCount(aligned ? nv : 0);
  // After a round moved the vertices from `previous` (the quads' scaled Jacobians there in
  // `before`): the moves undone that took a quad to kMinScaledJacobian or below.
  auto keepFromFolding = [&](const std::vector<Vec3>& previous) {
    auto spoiled = [](double was, double now) { return was > kMinScaledJacobian && now <= kMinScaledJacobian; };
    // The quads to check: all at first, then those depending on a vertex just put back.
    std::vector<int> check, reverted;
    jacobian.all(after);
    for (int q = 0; q < quads.numQuads(); ++q)
      if (spoiled(before[q], after[q])) check.push_back(q);
    while (!check.empty()) {
      reverted.clear();
      for (int q : check) {
        // Its own corners first; if they had not moved, the neighbours that turned its normals.
        bool own = false;
        for (int v : quads.quads[q])
          if (quads.positions[v] != previous[v]) quads.positions[v] = previous[v], reverted.push_back(v), own = true;
        if (own) continue;
        for (int c : quads.quads[q])
          for (int r : jacobian.quadsAround(c))
            for (int v : quads.quads[r])
              if (quads.positions[v] != previous[v]) quads.positions[v] = previous[v], reverted.push_back(v);
      }
      report.revertedMoves += int(reverted.size());
      std::vector<int> candidatesToCheck;
      jacobian.dependents(reverted, candidatesToCheck);
      jacobian.values(candidatesToCheck, after);
      check.clear();
      for (std::size_t i = 0; i < candidatesToCheck.size(); ++i)
        if (spoiled(before[candidatesToCheck[i]], after[i])) check.push_back(candidatesToCheck[i]);
    }
  };
  for (int it = 0; it < options.iterations; ++it) {
    const std::vector<Vec3> previous = quads.positions;
    jacobian.all(before);
    if (aligned) alignedTargets(quads, index, normals, options.triangleDirections, options.frozen, threads, alignedSum, alignedCount);
    const std::vector<char> moving = movingVertices(quads, jacobian, before, neighbours, aligned ? alignedCount : std::vector<int>{}, options.frozen,
                                                    options.keepGridAbove);
    // Each vertex's move depends on the previous positions only: the vertices are shared
    // among the worker threads (interleaved), the result the same for any number of them.
    std::vector<int> snapped(threads, 0);
    runOnWorkerThreads(threads, [&](int worker) {
      for (int v = worker; v < nv; v += threads) {
        next[v] = previous[v];
        if (fixed[v] || neighbours[v].empty() || !moving[v]) continue;
        Vec3 average = Vec3::Zero();
        for (int w : neighbours[v]) average += previous[w];
        average /= double(neighbours[v].size());
        // Around a quad already folded or nearly flat, the neighbours' average alone, which
        // unfolds; elsewhere the aligned rectangles' corners.
        bool good = true;
        for (int r : jacobian.quadsAround(v)) good = good && before[r] > kMinScaledJacobian;
        if (aligned && good && alignedCount[v] > 0) average = alignedSum[v] / double(alignedCount[v]);
        const Vec3& n = normals[index.closest(previous[v]).triangle];
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
            ++snapped[worker];
          }
        }
      }
    });
    for (int n : snapped) report.snappedMoves += n;
    quads.positions = next;
    keepFromFolding(previous);
  }
  if (aligned && options.fieldRelaxationRounds > 0)
    relaxRounds(quads, index, normals, options, fixed, neighbours, features.get(), jacobian, keepFromFolding, before, report);
  // Untangled twice from the smoothed positions: without, then with the nearest point on a
  // feature line among each vertex's candidates. Which local optimum the greedy moves reach
  // depends on that choice (a grid line beside a crease unfolds only once on it; elsewhere the
  // snap can trap a vertex), so the result with fewer folded quads is kept (the first on a tie).
  // Each is untangled first against the input surface's normal at each quad (the mean of the
  // normals of the surface triangles its corners lie on), which folded quads do not disturb,
  // then against the quads' own. With a feature to snap to and two threads, the second runs
  // beside the first, on a copy of the mesh; else only if the first left folds.
  const std::vector<Vec3> smoothed = quads.positions;
  std::vector<Vec3> reference(quads.numQuads(), Vec3::Zero());
  {
    std::vector<Vec3> at(nv, Vec3::Zero());
    runOnWorkerThreads(threads, [&](int worker) {
      for (int v = worker; v < nv; v += threads)
        if (!neighbours[v].empty()) at[v] = normals[index.closest(quads.positions[v]).triangle];
    });
    for (int q = 0; q < quads.numQuads(); ++q) {
      for (int v : quads.quads[q]) reference[q] += at[v];
      if (reference[q].norm() > 0) reference[q].normalize();
    }
  }
  auto untangleBoth = [&](QuadMesh& mesh, const QuadJacobian& own, bool snap, SmoothingReport& tried) {
    untangle(mesh, index, features.get(), slidable, fixed, neighbours, QuadJacobian(mesh, reference), tried, snap);
    untangle(mesh, index, features.get(), slidable, fixed, neighbours, own, tried, snap);
    std::vector<double> j;
    own.all(j);
    return int(std::count_if(j.begin(), j.end(), [](double x) { return x <= 0; }));
  };
  SmoothingReport keptReport = report, snappedReport = report;
  QuadMesh snapped;
  int keptFolds = 0, snappedFolds = std::numeric_limits<int>::max();
  if (features && threads >= 2) {
    snapped = quads;
    runOnWorkerThreads(2, [&](int worker) {
      if (worker == 0) keptFolds = untangleBoth(quads, jacobian, false, keptReport);
      else snappedFolds = untangleBoth(snapped, QuadJacobian(snapped), true, snappedReport);
    });
  } else {
    keptFolds = untangleBoth(quads, jacobian, false, keptReport);
    if (keptFolds > 0 && features) {
      snapped = quads;
      snapped.positions = smoothed;
      snappedFolds = untangleBoth(snapped, QuadJacobian(snapped), true, snappedReport);
    }
  }
  if (keptFolds > 0 && snappedFolds < keptFolds) quads.positions = std::move(snapped.positions), keptReport = snappedReport;
  report = keptReport;
  report.repairedFolds = repairFolds(quads, index, features.get(), normals, repairMoves, jacobian);
  // Quads left folded or nearly flat (scaled Jacobian at most kUntangleFloor), often with a
  // corner held on a feature line (at its end, where lines meet, or on a crease too bent to
  // slide along: on a scan, mostly short ridges of its noise): one more repair, in which those
  // corners may leave their line onto the surface (border and frozen vertices still stay). A
  // folded quad is worse than a vertex beside a crease (the dragon: its last 8 folds at 2% of
  // the diagonal all went, the least scaled Jacobian then 0.019).
  {
    std::vector<double> j;
    jacobian.all(j);
    std::vector<char> released = repairMoves;
    bool any = false;
    for (int q = 0; q < quads.numQuads(); ++q) {
      if (j[q] > kUntangleFloor) continue;
      any = true;
      for (int v : quads.quads[q])
        if (released[v] != kOnSurface && !onBorder[v] && !neighbours[v].empty() &&
            (options.frozen.empty() || !options.frozen[v]))
          released[v] = kOnSurface;
    }
    if (any) report.repairedFolds += repairFolds(quads, index, features.get(), normals, released, jacobian, kUntangleFloor);
  }
  return report;
}

}  // namespace

SmoothingReport smoothQuadMesh(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                               const std::vector<std::array<int, 3>>& surfaceTriangles,
                               const SmoothingOptions& options) {
  const int nv = quads.numVertices();
  if (options.frozen.empty() || options.frozen.size() != std::size_t(nv) || options.iterations <= 0)
    return smoothWhole(quads, surfacePositions, surfaceTriangles, options);
  // Only some vertices move: they are smoothed in the part of the mesh their figures depend
  // on, the quads within two rings of them (the scaled Jacobian of a quad around a moving
  // vertex takes the normals at its corners from the quads around those), the rest of that
  // part frozen. The moving vertices' own quads and their neighbours' are all in the part, so
  // its rim (a border there) holds only frozen vertices.
  std::vector<char> near(nv, 0);
  for (int v = 0; v < nv; ++v) near[v] = !options.frozen[v];
  growAcrossQuads(quads, near, 1);
  QuadMesh part;
  SmoothingOptions partOptions = options;
  partOptions.frozen.clear();
  std::vector<int> index(nv, -1), original;
  for (int q = 0; q < quads.numQuads(); ++q) {
    const auto& f = quads.quads[q];
    if (!(near[f[0]] || near[f[1]] || near[f[2]] || near[f[3]])) continue;
    std::array<int, 4> g;
    for (int k = 0; k < 4; ++k) {
      if (index[f[k]] < 0) {
        index[f[k]] = int(original.size());
        original.push_back(f[k]);
        part.positions.push_back(quads.positions[f[k]]);
        partOptions.frozen.push_back(options.frozen[f[k]]);
      }
      g[k] = index[f[k]];
    }
    part.quads.push_back(g);
    if (q < int(quads.quadPatch.size())) part.quadPatch.push_back(quads.quadPatch[q]);
  }
  if (part.quads.empty()) return SmoothingReport{};
  SmoothingReport report = smoothWhole(part, surfacePositions, surfaceTriangles, partOptions);
  for (std::size_t i = 0; i < original.size(); ++i)
    if (!options.frozen[original[i]]) quads.positions[original[i]] = part.positions[i];
  return report;
}

namespace {

}  // namespace

int restoreSampledPositions(QuadMesh& quads, const std::vector<Vec3>& sampled, const std::vector<Vec3>& far,
                            double radius) {
  const int nv = quads.numVertices();
  if (int(sampled.size()) != nv) throw std::invalid_argument("restoreSampledPositions: one sampled position per vertex");
  if (far.empty() || !(radius > 0)) return 0;
  // The far points bucketed in cells of `radius`. A far point within radius / 2 returns a
  // vertex fully, so the search stops at the first one found there: a pass far from the bound
  // has millions of far points.
  PointBuckets cells(far, radius);
  cells.addAll();
  const QuadJacobian jacobian(quads);
  std::vector<int> around;
  std::vector<double> before, after;
  // Vertex by vertex in index order: a return that folds or flattens a quad that depends on the
  // vertex (given where the others are by then) is not made.
  int count = 0;
  for (int v = 0; v < nv; ++v) {
    if (jacobian.quadsAround(v).empty() || quads.positions[v] == sampled[v]) continue;
    const Vec3 smoothed = quads.positions[v];
    const double nearest = cells.nearest(smoothed, radius / 2);
    if (!(nearest < radius)) continue;
    const double share = std::min(1.0, 2.0 * (1.0 - nearest / radius));
    jacobian.dependents(v, around);
    jacobian.values(around, before);
    quads.positions[v] = smoothed + (sampled[v] - smoothed) * share;
    jacobian.values(around, after);
    if (spoilsQuads(before, after, kMinScaledJacobian)) quads.positions[v] = smoothed;
    else ++count;
  }
  return count;
}

}  // namespace fcql
