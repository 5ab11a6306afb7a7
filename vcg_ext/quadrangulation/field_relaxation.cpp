#include "quadrangulation/field_relaxation.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

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
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> rhs;
  entries.reserve(std::size_t(quads.numQuads()) * 4 * 2 * 4 + std::size_t(n));
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
        const double w = meanEdge / length * (axis == along ? kFieldRelaxationLengthWeight : 1.0);
        const int row = int(rhs.size());
        if (var[b] >= 0) {
          entries.emplace_back(row, var[b], w * frame[axis].dot(t1[b]));
          entries.emplace_back(row, var[b] + 1, w * frame[axis].dot(t2[b]));
        }
        if (var[a] >= 0) {
          entries.emplace_back(row, var[a], -w * frame[axis].dot(t1[a]));
          entries.emplace_back(row, var[a] + 1, -w * frame[axis].dot(t2[a]));
        }
        rhs.push_back(w * (target[axis] - now[axis]));
      }
    }
  }
  const double root = std::sqrt(anchor);
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(int(rhs.size()), i, root);
    rhs.push_back(0);
  }
  Eigen::SparseMatrix<double> A(int(rhs.size()), n);
  A.setFromTriplets(entries.begin(), entries.end());
  std::vector<Eigen::Triplet<double>>().swap(entries);
  const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), Eigen::Index(rhs.size()));
  const Eigen::SparseMatrix<double> normal = A.transpose() * A;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) return result;
  const Eigen::VectorXd x = solver.solve(A.transpose() * b);
  if (solver.info() != Eigen::Success || !x.allFinite()) return result;
  for (int v = 0; v < nv; ++v)
    if (var[v] >= 0) result.positions[v] = surface.closest(P[v] + t1[v] * x[var[v]] + t2[v] * x[var[v] + 1]).point;
  result.solved = true;
  return result;
}

}  // namespace fcql
