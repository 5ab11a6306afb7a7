#include "mesh/closest_point_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fcql {

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) return a;  // degenerate triangle: any vertex
  return a + ab * (vb / denom) + ac * (vc / denom);
}

ClosestPointIndex::ClosestPointIndex(const SurfaceMesh& mesh) : ClosestPointIndex(mesh.positions(), mesh.faces()) {}

ClosestPointIndex::ClosestPointIndex(std::vector<Vec3> positions, std::vector<std::array<int, 3>> triangles)
    : positions_(std::move(positions)), triangles_(std::move(triangles)) {
  if (triangles_.empty()) throw std::invalid_argument("closest-point index: no triangles");
  const int nv = int(positions_.size());
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const auto& t : triangles_)
    for (int v : t) {
      if (v < 0 || v >= nv) throw std::invalid_argument("closest-point index: vertex index out of range");
      lo = lo.cwiseMin(positions_[v]);
      hi = hi.cwiseMax(positions_[v]);
    }
  const Vec3 extent = hi - lo;
  const double diag = std::max(extent.norm(), 1e-30);
  // About two cells per triangle, with no side thinner than a thousandth of the diagonal.
  const Vec3 padded = extent.cwiseMax(Vec3::Constant(diag * 1e-3));
  const double volume = padded.x() * padded.y() * padded.z();
  cell_ = std::cbrt(volume / (2.0 * triangles_.size()));
  cell_ = std::max(cell_, diag / 1024.0);
  origin_ = lo - Vec3::Constant(cell_ * 0.5);
  for (int k = 0; k < 3; ++k) dims_[k] = std::max(1, int(std::ceil((extent[k] + cell_) / cell_)));

  const int numCells = dims_[0] * dims_[1] * dims_[2];
  std::vector<int> count(numCells + 1, 0);
  auto forCells = [&](const std::array<int, 3>& t, auto&& f) {
    Vec3 tlo = positions_[t[0]].cwiseMin(positions_[t[1]]).cwiseMin(positions_[t[2]]);
    Vec3 thi = positions_[t[0]].cwiseMax(positions_[t[1]]).cwiseMax(positions_[t[2]]);
    std::array<int, 3> a = cellOf(tlo), b = cellOf(thi);
    for (int z = a[2]; z <= b[2]; ++z)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int x = a[0]; x <= b[0]; ++x) f(cellIndex(x, y, z));
  };
  for (const auto& t : triangles_) forCells(t, [&](int c) { ++count[c + 1]; });
  for (int c = 0; c < numCells; ++c) count[c + 1] += count[c];
  cellStart_ = count;
  cellTriangles_.resize(cellStart_.back());
  std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (int i = 0; i < int(triangles_.size()); ++i) forCells(triangles_[i], [&](int c) { cellTriangles_[fill[c]++] = i; });
  boxLow_.resize(triangles_.size());
  boxHigh_.resize(triangles_.size());
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto& t = triangles_[i];
    boxLow_[i] = positions_[t[0]].cwiseMin(positions_[t[1]]).cwiseMin(positions_[t[2]]);
    boxHigh_[i] = positions_[t[0]].cwiseMax(positions_[t[1]]).cwiseMax(positions_[t[2]]);
  }
}

std::array<int, 3> ClosestPointIndex::cellOf(const Vec3& p) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) {
    double x = std::floor((p[k] - origin_[k]) / cell_);
    c[k] = int(std::min<double>(dims_[k] - 1, std::max(0.0, x)));
  }
  return c;
}

ClosestPoint ClosestPointIndex::closest(const Vec3& p) const {
  ClosestPoint best;
  best.distance = std::numeric_limits<double>::infinity();
  const std::array<int, 3> c = cellOf(p);
  const int maxRing = std::max({dims_[0], dims_[1], dims_[2]});
  auto visit = [&](int x, int y, int z) {
    const int cell = cellIndex(x, y, z);
    for (int i = cellStart_[cell]; i < cellStart_[cell + 1]; ++i) {
      const int t = cellTriangles_[i];
      // Its bounding box no nearer than the best so far: the triangle cannot be nearer.
      const Vec3 outside = (boxLow_[t] - p).cwiseMax(p - boxHigh_[t]).cwiseMax(Vec3::Zero());
      if (outside.squaredNorm() >= best.distance * best.distance) continue;
      const auto& tri = triangles_[t];
      Vec3 q = closestPointOnTriangle(p, positions_[tri[0]], positions_[tri[1]], positions_[tri[2]]);
      double d = (q - p).norm();
      if (d < best.distance) {
        best.distance = d;
        best.point = q;
        best.triangle = t;
      }
    }
  };
  // Distance from p to any cell of shell r or beyond: such a cell is r steps from p's cell
  // along some axis, so it lies beyond the face of the box of shells < r on that side (a side
  // where the grid still has cells). Measured from p itself, not from the edge of its cell: a
  // point near the surface usually finds its nearest triangle in its own cell and stops there.
  auto beyond = [&](int r) {
    double gap = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      if (c[k] - r >= 0) gap = std::min(gap, p[k] - (origin_[k] + (c[k] - r + 1) * cell_));
      if (c[k] + r < dims_[k]) gap = std::min(gap, origin_[k] + (c[k] + r) * cell_ - p[k]);
    }
    return gap;
  };
  // The squared distance from p to the slab of cells i along axis k (0 inside it): a cell no
  // nearer than the best so far holds no nearer triangle, and is skipped. So a shell beyond p's
  // own cell costs only the cells next to the walls p is near, not all of it.
  auto gap2 = [&](int k, int i) {
    const double lo = origin_[k] + i * cell_, hi = lo + cell_;
    const double d = p[k] < lo ? lo - p[k] : p[k] > hi ? p[k] - hi : 0.0;
    return d * d;
  };
  for (int r = 0; r <= maxRing; ++r) {
    if (best.triangle >= 0 && best.distance <= beyond(r)) break;
    for (int z = c[2] - r; z <= c[2] + r; ++z) {
      if (z < 0 || z >= dims_[2]) continue;
      const double dz = gap2(2, z);
      if (dz >= best.distance * best.distance) continue;
      for (int y = c[1] - r; y <= c[1] + r; ++y) {
        if (y < 0 || y >= dims_[1]) continue;
        const double dyz = dz + gap2(1, y);
        if (dyz >= best.distance * best.distance) continue;
        const bool faceShell = std::abs(z - c[2]) == r || std::abs(y - c[1]) == r;
        for (int x = c[0] - r; x <= c[0] + r; x += (faceShell ? 1 : std::max(1, 2 * r))) {
          if (x < 0 || x >= dims_[0]) continue;
          if (dyz + gap2(0, x) >= best.distance * best.distance) continue;
          visit(x, y, z);
        }
      }
    }
  }
  return best;
}

}  // namespace fcql
