#include "field/singularity_pairs.h"

#include "field/field_analysis.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <cstdlib>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace fcql {

namespace {

constexpr double kTurnStep = 5.0 * 3.14159265358979323846 / 180.0;  ///< 5 degrees
constexpr int kMaxSteps = 9;  ///< up to 45 degrees either way: a cross repeats every 90

/// The turns (in steps of kTurnStep) of the two crosses on a pair's edge, tried in this order:
/// one cross alone, the least turn first (the first face before the second, counter-clockwise
/// before clockwise), then both together, the least in all first.
const std::vector<std::pair<int, int>>& turns() {
  static const std::vector<std::pair<int, int>> all = [] {
    std::vector<std::pair<int, int>> t, both;
    for (int step = 1; step <= kMaxSteps; ++step)
      for (int sign : {1, -1}) t.emplace_back(sign * step, 0), t.emplace_back(0, sign * step);
    for (int i = -kMaxSteps; i <= kMaxSteps; ++i)
      for (int j = -kMaxSteps; j <= kMaxSteps; ++j)
        if (i != 0 && j != 0) both.emplace_back(i, j);
    std::stable_sort(both.begin(), both.end(), [](const auto& x, const auto& y) {
      return std::abs(x.first) + std::abs(x.second) < std::abs(y.first) + std::abs(y.second);
    });
    t.insert(t.end(), both.begin(), both.end());
    return t;
  }();
  return all;
}

using Complex = std::complex<double>;

/// Close pairs: a neighbourhood that does not do it is tried once more this many times wider.
constexpr double kWiderNeighbourhood = 2;
/// The neighbourhood's radius is at least this many mean edges.
constexpr double kMinRadiusEdges = 2;

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

/// The faces reached from vertex s's star across interior edges, through faces whose centroid
/// lies within `radius` of the segment [a, b] (s's star itself always).
std::vector<int> neighbourhood(const SurfaceMesh& mesh, int s, const Vec3& a, const Vec3& b, double radius) {
  std::vector<int> faces;
  std::unordered_set<int> seen;
  for (const StarCorner& c : mesh.star(s))
    if (seen.insert(c.face).second) faces.push_back(c.face);
  for (std::size_t k = 0; k < faces.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const int g = mesh.adjacentFace(faces[k], i);
      if (g < 0 || seen.count(g) || distanceToSegment(mesh.faceCentroid(g), a, b) > radius) continue;
      seen.insert(g);
      faces.push_back(g);
    }
  return faces;
}

/// The smoothest field on the faces of `region` not marked in `fixedFace`, the others held
/// (see the header). False if there is nothing to solve or no finite solution.
bool smoothestInside(const SurfaceMesh& mesh, CrossField& field, const std::vector<int>& region,
                     const std::vector<std::array<double, 3>>& rho, const std::vector<char>& fixedFace) {
  std::vector<int> free;  // the faces to solve for, in the region's order (unknown a is free[a])
  std::unordered_map<int, int> unknown;
  for (int f : region)
    if (fixedFace.empty() || !fixedFace[f]) unknown.emplace(f, int(free.size())), free.push_back(f);
  const int n = int(free.size());
  if (n == 0) return false;
  auto held = [&](int f) { return std::polar(1.0, 4 * angleInFaceFrame(mesh, f, field.u[f])); };
  std::vector<Eigen::Triplet<Complex>> lower;
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(n);
  for (int a = 0; a < n; ++a)
    for (int i = 0, f = free[a]; i < 3; ++i) {
      const int g = mesh.adjacentFace(f, i);
      if (g < 0) continue;
      const auto other = unknown.find(g);
      if (other != unknown.end() && g < f) continue;  // free-free edges once
      const auto [r, w] = edgeSmoothness(mesh, f, i, rho[f][i]);  // z_g ≈ r z_f
      diagonal[a] += w;
      if (other == unknown.end()) {
        rhs[a] += w * std::conj(r) * held(g);
        continue;
      }
      const int b = other->second;
      diagonal[b] += w;
      // w |z_g − r z_f|²: the entry (g, f) is −w r, its mirror the conjugate.
      if (b > a) lower.emplace_back(b, a, -w * r);
      else lower.emplace_back(a, b, -w * std::conj(r));
    }
  const double meanDiagonal = diagonal.sum() > 0 ? diagonal.sum() / n : 1.0;
  for (int a = 0; a < n; ++a) lower.emplace_back(a, a, diagonal[a] + 1e-12 * meanDiagonal);
  Eigen::SparseMatrix<Complex> system(n, n);
  system.setFromTriplets(lower.begin(), lower.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Complex>, Eigen::Lower> solver(system);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::VectorXcd z = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !z.allFinite()) return false;
  for (int a = 0; a < n; ++a) {
    if (!(std::abs(z[a]) > 0)) continue;
    const int f = free[a];
    const double theta = std::arg(z[a]) / 4;
    field.u[f] = std::cos(theta) * mesh.faceFrameX(f) + std::sin(theta) * mesh.faceFrameY(f);
  }
  return true;
}

}  // namespace

int cancelAdjacentSingularityPairs(const SurfaceMesh& mesh, CrossField& field, const std::vector<char>& fixedFace) {
  std::vector<int> q = computeVertexIndices(mesh, field);
  auto isFixed = [&](int f) { return !fixedFace.empty() && fixedFace[f] != 0; };
  int cancelled = 0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      const int g = mesh.adjacentFace(f, i);
      if (g < f) continue;  // a border edge, or seen from g
      const int a = mesh.vertex(f, i), b = mesh.vertex(f, (i + 1) % 3);
      if (mesh.isBorderVertex(a) || mesh.isBorderVertex(b) || q[a] * q[b] >= 0) continue;
      // The vertices whose index a change of f's or g's cross can move.
      std::vector<int> around;
      for (int h : {f, g})
        for (int c = 0; c < 3; ++c)
          if (std::find(around.begin(), around.end(), mesh.vertex(h, c)) == around.end()) around.push_back(mesh.vertex(h, c));
      auto irregular = [&] {
        int sum = 0;
        for (int v : around) sum += std::abs(q[v]);
        return sum;
      };
      // A quarter off each end at a time (a ±1/2 pair takes two), while some turn does it.
      while (q[a] * q[b] < 0) {
        const int before = irregular(), qa = std::abs(q[a]), qb = std::abs(q[b]);
        std::vector<int> savedQ;
        for (int v : around) savedQ.push_back(q[v]);
        bool done = false;
        for (const auto& turn : turns()) {
          if ((turn.first != 0 && isFixed(f)) || (turn.second != 0 && isFixed(g))) continue;
          const Vec3 fromF = field.u[f], fromG = field.u[g];
          field.u[f] = rotateInPlane(fromF, mesh.faceNormal(f), turn.first * kTurnStep);
          field.u[g] = rotateInPlane(fromG, mesh.faceNormal(g), turn.second * kTurnStep);
          for (int v : around) q[v] = vertexIndexQuarters(mesh, field, v);
          // A quarter less at both ends, and the count around down by just that.
          if (std::abs(q[a]) == qa - 1 && std::abs(q[b]) == qb - 1 && irregular() == before - 2) {
            done = true;
            ++cancelled;
            break;
          }
          field.u[f] = fromF, field.u[g] = fromG;
          for (std::size_t k = 0; k < around.size(); ++k) q[around[k]] = savedQ[k];
        }
        if (!done) break;
      }
    }
  return cancelled;
}

int cancelCloseSingularityPairs(const SurfaceMesh& mesh, CrossField& field, double reach,
                                const std::vector<std::array<double, 3>>& connectionCorrection,
                                const std::vector<char>& fixedFace) {
  if (!(reach > 0) || int(connectionCorrection.size()) != mesh.numFaces()) return 0;
  std::vector<int> q = computeVertexIndices(mesh, field);
  std::vector<int> plus, minus;
  for (int v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.isBorderVertex(v)) continue;
    if (q[v] == 1) plus.push_back(v);
    if (q[v] == -1) minus.push_back(v);
  }
  // Mutually nearest pairs only: each quarter's nearest opposite one, if it is its nearest too
  // (on a noisy scan with hundreds of singularities, trying every pair within reach cost more
  // than the rest of the field and cancelled no more).
  auto nearest = [&](int v, const std::vector<int>& others) {
    std::pair<double, int> best(std::numeric_limits<double>::infinity(), -1);
    for (int w : others) best = std::min(best, std::make_pair((mesh.position(v) - mesh.position(w)).norm(), w));
    return best;
  };
  std::vector<std::tuple<double, int, int>> pairs;  // distance, +1/4, −1/4
  for (int s : plus) {
    const auto [d, t] = nearest(s, minus);
    if (t >= 0 && d <= reach && nearest(t, plus).second == s) pairs.emplace_back(d, s, t);
  }
  std::sort(pairs.begin(), pairs.end());
  int cancelled = 0;
  for (const auto& [d, s, t] : pairs) {
    if (q[s] != 1 || q[t] != -1) continue;  // one of them went with an earlier pair
    for (double wider : {1.0, kWiderNeighbourhood}) {
      const double radius = wider * std::max(d, kMinRadiusEdges * mesh.meanEdgeLength());
      const std::vector<int> region = neighbourhood(mesh, s, mesh.position(s), mesh.position(t), radius);
      // The vertices whose index the region's crosses count in: every corner of its faces.
      std::vector<int> around;
      for (int f : region)
        for (int c = 0; c < 3; ++c) around.push_back(mesh.vertex(f, c));
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      if (!std::binary_search(around.begin(), around.end(), t)) continue;  // not reached across the surface
      std::vector<Vec3> savedU;
      for (int f : region) savedU.push_back(field.u[f]);
      std::vector<int> savedQ;
      for (int v : around) savedQ.push_back(q[v]);
      bool gone = smoothestInside(mesh, field, region, connectionCorrection, fixedFace);
      if (gone) {
        // Two quarters fewer in all (a third singularity of the cluster may move), no new
        // index of a half or more, the border's as it was.
        int before = 0, after = 0;
        for (std::size_t k = 0; k < around.size(); ++k) {
          const int v = around[k];
          q[v] = vertexIndexQuarters(mesh, field, v);
          before += std::abs(savedQ[k]), after += std::abs(q[v]);
          if ((std::abs(q[v]) > 1 && q[v] != savedQ[k]) || (mesh.isBorderVertex(v) && q[v] != savedQ[k])) gone = false;
        }
        gone = gone && after <= before - 2;
      }
      if (gone) {
        ++cancelled;
        break;
      }
      for (std::size_t k = 0; k < region.size(); ++k) field.u[region[k]] = savedU[k];
      for (std::size_t k = 0; k < around.size(); ++k) q[around[k]] = savedQ[k];
    }
  }
  return cancelled;
}

}  // namespace fcql
