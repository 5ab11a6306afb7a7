#include "quadrangulation/field_relaxation.h"

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>

namespace fcql {

FieldRelaxation relaxTowardsField(const QuadMesh& quads, const ClosestPointIndex& surface,
                                  const std::vector<Vec3>& triangleNormals, const std::vector<Vec3>& triangleDirections,
                                  const std::vector<char>& movable, double anchor) {
  FieldRelaxation result;
  result.positions = quads.positions;
  const int nv = quads.numVertices();
  if (int(movable.size()) != nv || !(anchor > 0) || quads.numQuads() == 0) return result;
  const auto& P = quads.positions;
  // Unknowns: two per movable vertex, along t1 and t2 of its tangent plane.
  std::vector<int> var(nv, -1);
  std::vector<Vec3> t1(nv, Vec3::Zero()), t2(nv, Vec3::Zero());
  int n = 0;
  for (int v = 0; v < nv; ++v) {
    if (!movable[v]) continue;
    const Vec3& normal = triangleNormals[surface.closest(P[v]).triangle];
    if (normal.isZero()) continue;
    t1[v] = normal.unitOrthogonal();
    t2[v] = normal.cross(t1[v]);
    var[v] = n;
    n += 2;
  }
  if (n == 0) return result;
  double meanEdge = 0;
  for (const auto& f : quads.quads)
    for (int k = 0; k < 4; ++k) meanEdge += (P[f[(k + 1) % 4]] - P[f[k]]).norm();
  meanEdge /= 4.0 * quads.numQuads();
  // The normal equations assembled directly, in compressed rows (the matrix is symmetric, so
  // they are its compressed columns too): per unknown vertex, its 2×2 blocks with itself and
  // the unknown vertices it shares a quad edge with.
  std::vector<std::vector<int>> adjacent(nv);
  for (const auto& f : quads.quads)
    for (int k = 0; k < 4; ++k) {
      const int a = f[k], b = f[(k + 1) % 4];
      if (var[a] >= 0 && var[b] >= 0) adjacent[a].push_back(b), adjacent[b].push_back(a);
    }
  std::vector<int> outer(std::size_t(n) + 1, 0);
  for (int v = 0; v < nv; ++v) {
    if (var[v] < 0) continue;
    auto& list = adjacent[v];
    list.push_back(v);
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    outer[var[v] + 1] = outer[var[v] + 2] = 2 * int(list.size());
  }
  for (int i = 0; i < n; ++i) outer[i + 1] += outer[i];
  std::vector<int> inner(std::size_t(outer[n]));
  std::vector<double> values(inner.size(), 0.0);
  for (int v = 0; v < nv; ++v) {
    if (var[v] < 0) continue;
    for (int p = 0; p < 2; ++p) {
      int at = outer[var[v] + p];
      for (int w : adjacent[v]) inner[at++] = var[w], inner[at++] = var[w] + 1;
    }
  }
  // The entry of row (vertex v, coordinate p) and column (vertex w, coordinate q).
  auto entry = [&](int v, int p, int w, int q) -> double& {
    const auto& list = adjacent[v];
    const int k = int(std::lower_bound(list.begin(), list.end(), w) - list.begin());
    return values[std::size_t(outer[var[v] + p] + 2 * k + q)];
  };
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (const auto& f : quads.quads) {
    const int t = surface.closest((P[f[0]] + P[f[1]] + P[f[2]] + P[f[3]]) / 4).triangle;
    const Vec3& normal = triangleNormals[t];
    Vec3 d1 = triangleDirections[t] - normal * normal.dot(triangleDirections[t]);
    if (normal.isZero() || !(d1.norm() > 0)) continue;
    d1.normalize();
    const std::array<Vec3, 2> frame{d1, normal.cross(d1)};
    for (int k = 0; k < 4; ++k) {
      const int a = f[k], b = f[(k + 1) % 4];
      const Vec3 e = P[b] - P[a];
      const Vec2 now(frame[0].dot(e), frame[1].dot(e));
      const double length = now.norm();
      if (!(length > 0)) continue;
      // The cross direction nearest to the edge, at the edge's length; the residual relative
      // to the edge's length (an angle, times the mean edge), its length kept more loosely.
      const int along = std::abs(now.x()) >= std::abs(now.y()) ? 0 : 1;
      Vec2 target = Vec2::Zero();
      target[along] = std::copysign(length, now[along]);
      for (int axis = 0; axis < 2; ++axis) {
        // The row: Σ coefficient · unknown = value, over (vertex, coordinate) pairs.
        const double w = meanEdge / length * (axis == along ? kFieldRelaxationLengthWeight : 1.0);
        const std::array<int, 2> vertex{b, a};
        std::array<std::array<double, 2>, 2> coefficient;
        for (int s = 0; s < 2; ++s) {
          const double sign = s == 0 ? w : -w;
          coefficient[s] = {sign * frame[axis].dot(t1[vertex[s]]), sign * frame[axis].dot(t2[vertex[s]])};
        }
        const double value = w * (target[axis] - now[axis]);
        for (int s = 0; s < 2; ++s) {
          if (var[vertex[s]] < 0) continue;
          for (int p = 0; p < 2; ++p) {
            rhs[var[vertex[s]] + p] += coefficient[s][p] * value;
            for (int r = 0; r < 2; ++r) {
              if (var[vertex[r]] < 0) continue;
              for (int q = 0; q < 2; ++q) entry(vertex[s], p, vertex[r], q) += coefficient[s][p] * coefficient[r][q];
            }
          }
        }
      }
    }
  }
  for (int v = 0; v < nv; ++v)
    if (var[v] >= 0)
      for (int p = 0; p < 2; ++p) entry(v, p, v, p) += anchor;
  const Eigen::Map<const Eigen::SparseMatrix<double>> normalMatrix(n, n, outer[n], outer.data(), inner.data(), values.data());
  // Conjugate gradients (the anchor bounds the condition number whatever the mesh's size).
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
  solver.setTolerance(kFieldRelaxationTolerance);
  solver.setMaxIterations(kFieldRelaxationIterations);
  solver.compute(normalMatrix);
  const Eigen::VectorXd x = solver.solve(rhs);
  if (!x.allFinite()) return result;
  for (int v = 0; v < nv; ++v)
    if (var[v] >= 0) result.positions[v] = surface.closest(P[v] + t1[v] * x[var[v]] + t2[v] * x[var[v] + 1]).point;
  result.solved = true;
  return result;
}

}  // namespace fcql
