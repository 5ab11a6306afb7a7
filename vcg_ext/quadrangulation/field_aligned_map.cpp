#include "quadrangulation/field_aligned_map.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <deque>

namespace fcql {
namespace {

struct TriangleFrame {
  Vec3 normal = Vec3::Zero();
  double area = 0;
  std::array<Vec3, 3> gradient;  ///< ∇φ_i of the hat functions
};

TriangleFrame frameOf(const std::array<Vec3, 3>& p) {
  TriangleFrame f;
  const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
  const double twice = n.norm();
  f.area = twice / 2;
  if (!(twice > 1e-300)) {
    for (auto& g : f.gradient) g = Vec3::Zero();
    return f;
  }
  f.normal = n / twice;
  for (int i = 0; i < 3; ++i) f.gradient[i] = f.normal.cross(p[(i + 2) % 3] - p[(i + 1) % 3]) / twice;
  return f;
}

/// d turned by k quarter turns about n.
Vec3 quarterTurns(const Vec3& d, const Vec3& n, int k) {
  Vec3 r = d;
  for (int i = 0; i < (k & 3); ++i) r = n.cross(r);
  return r;
}

}  // namespace

int foldedTriangles(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec2>& uv, double minArea) {
  double total = 0;
  std::vector<double> area(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Vec2 a = uv[triangles[t][1]] - uv[triangles[t][0]], b = uv[triangles[t][2]] - uv[triangles[t][0]];
    area[t] = a.x() * b.y() - a.y() * b.x();
    total += std::abs(area[t]);
  }
  const double limit = triangles.empty() ? 0 : minArea * total / double(triangles.size());
  int folded = 0;
  for (double a : area)
    if (!(a > limit)) ++folded;
  return folded;
}

FieldAlignedRows fieldAlignedRows(const FieldAlignedProblem& pb) {
  const int nt = int(pb.triangles.size()), nw = int(pb.start.size());
  FieldAlignedRows rows;
  if (nt == 0 || nw == 0) return rows;
  std::vector<TriangleFrame> frame(nt);
  for (int t = 0; t < nt; ++t) frame[t] = frameOf(pb.corners[t]);

  // Comb the cross over the patch: per triangle one direction, each turned to agree with its
  // neighbour's, carried across their shared edge.
  std::vector<Vec3> combed(nt, Vec3::Zero());
  std::vector<char> done(nt, 0);
  auto tangent = [&](int t, const Vec3& d) {
    Vec3 x = d - frame[t].normal * frame[t].normal.dot(d);
    const double l = x.norm();
    return l > 1e-300 ? Vec3(x / l) : Vec3::Zero();
  };
  for (int seed = 0; seed < nt; ++seed) {
    if (done[seed]) continue;
    done[seed] = 1;
    combed[seed] = tangent(seed, pb.direction[seed]);
    std::deque<int> queue{seed};
    while (!queue.empty()) {
      const int t = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        const int o = pb.neighbours[t][i];
        if (o < 0 || done[o]) continue;
        done[o] = 1;
        Vec3 e = pb.corners[t][(i + 1) % 3] - pb.corners[t][i];
        if (e.norm() > 0) e.normalize();
        const Vec3& d = combed[t];
        const Vec3 carried = e * d.dot(e) + frame[o].normal.cross(e) * d.dot(frame[t].normal.cross(e));
        const Vec3 base = tangent(o, pb.direction[o]);
        int best = 0;
        double bestDot = -2;
        for (int k = 0; k < 4; ++k) {
          const double dot = quarterTurns(base, frame[o].normal, k).dot(carried);
          if (dot > bestDot) bestDot = dot, best = k;
        }
        combed[o] = quarterTurns(base, frame[o].normal, best);
        queue.push_back(o);
      }
    }
  }
  // Which quarter turn of the combed cross is the u axis: the one that best agrees with the
  // constrained edges (the boundary: along side 0, u grows and v stays, and so on), each edge
  // e of the surface going to Δ = start[b] − start[a], so that e·d1 ~ Δu and e·d2 ~ Δv.
  std::array<double, 4> score{0, 0, 0, 0};
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = pb.triangles[t][i], b = pb.triangles[t][(i + 1) % 3];
      if (pb.constraint[a] == FieldAlignedProblem::Free || pb.constraint[b] == FieldAlignedProblem::Free) continue;
      const Vec3 e = pb.corners[t][(i + 1) % 3] - pb.corners[t][i];
      const Vec2 delta = pb.start[b] - pb.start[a];
      for (int k = 0; k < 4; ++k)
        score[k] += quarterTurns(combed[t], frame[t].normal, k).dot(e) * delta.x() +
                    quarterTurns(combed[t], frame[t].normal, k + 1).dot(e) * delta.y();
    }
  int turn = 0;
  for (int k = 1; k < 4; ++k)
    if (score[k] > score[turn]) turn = k;

  for (int axis = 0; axis < 2; ++axis)
    for (int t = 0; t < nt; ++t) {
      if (!(frame[t].area > 0)) continue;
      const Vec3 d1 = quarterTurns(combed[t], frame[t].normal, turn + axis);  // along this axis
      const Vec3 d2 = frame[t].normal.cross(d1);                             // across it
      const double root = std::sqrt(frame[t].area);
      for (int r = 0; r < 2; ++r) {
        const Vec3& d = r == 0 ? d2 : d1;
        const double weight = r == 0 ? root * std::sqrt(pb.alignWeight) : root;
        FieldAlignedRows::Row row;
        for (int i = 0; i < 3; ++i) {
          row.wedge[i] = pb.triangles[t][i];
          row.coefficient[i] = weight * frame[t].gradient[i].dot(d);
        }
        row.scale = r == 1 ? -weight : 0.0;
        rows.axis[axis].push_back(row);
      }
    }
  return rows;
}

FieldAlignedResult solveFieldAlignedMap(const FieldAlignedProblem& pb) {
  const int nw = int(pb.start.size());
  FieldAlignedResult result;
  result.uv = pb.start;
  if (pb.triangles.empty() || nw == 0) return result;
  const FieldAlignedRows rows = fieldAlignedRows(pb);

  // Two independent least-squares problems, u (axis d1) and v (axis d2).
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<int> var(nw, -1);
    int nv = 0;
    for (int w = 0; w < nw; ++w) {
      const auto c = pb.constraint[w];
      const bool fixed = c == FieldAlignedProblem::Fixed || (axis == 0 ? c == FieldAlignedProblem::FixU : c == FieldAlignedProblem::FixV);
      if (!fixed) var[w] = nv++;
    }
    if (nv == 0) continue;
    const int scale = nv;  // the unknown scale a (or b)
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> rhs;
    int row = 0;
    for (const FieldAlignedRows::Row& r : rows.axis[axis]) {
      double b = 0;
      for (int i = 0; i < 3; ++i) {
        const int w = r.wedge[i];
        if (var[w] >= 0) entries.emplace_back(row, var[w], r.coefficient[i]);
        else b -= r.coefficient[i] * pb.start[w][axis];
      }
      if (r.scale != 0) entries.emplace_back(row, scale, r.scale);
      rhs.push_back(b);
      ++row;
    }
    Eigen::SparseMatrix<double> M(row, nv + 1);
    M.setFromTriplets(entries.begin(), entries.end());
    const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), row);
    const Eigen::SparseMatrix<double> normal = M.transpose() * M;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success) return FieldAlignedResult{pb.start, false};
    const Eigen::VectorXd x = solver.solve(M.transpose() * b);
    if (solver.info() != Eigen::Success || !x.allFinite()) return FieldAlignedResult{pb.start, false};
    for (int w = 0; w < nw; ++w)
      if (var[w] >= 0) result.uv[w][axis] = x[var[w]];
  }
  result.solved = true;
  return result;
}

}  // namespace fcql
