#include "quadrangulation/patch_map.h"

#include "quadrangulation/field_aligned_map.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fcql {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

int PatchMap::wedge(int t, int c) const {
  int x = slotOf_.at(t * 3 + c);
  while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
  return x;
}

PatchMap::PatchMap(const PatchLayout& layout, int patch, const std::vector<int>& triangles,
                   const std::unordered_map<std::uint64_t, int>& halfEdges, const std::function<Vec2(int)>& boundaryUv,
                   const PatchGuide* guide, bool map)
    : layout_(layout), patch_(patch), triangles_(triangles) {
  for (int t : triangles_)
    for (int c = 0; c < 3; ++c) {
      slotOf_[t * 3 + c] = int(parent_.size());
      parent_.push_back(int(parent_.size()));
    }
  auto cornerIn = [&](int t, int v) {
    for (int c = 0; c < 3; ++c)
      if (layout.triangles[t][c] == v) return c;
    return -1;
  };
  auto unite = [&](int a, int b) { parent_[wedge(a / 3, a % 3)] = wedge(b / 3, b % 3); };
  for (int t : triangles_)
    for (int i = 0; i < 3; ++i) {
      if (layout.edgeCurve[t][i] != -1) continue;
      int a = layout.triangles[t][i], b = layout.triangles[t][(i + 1) % 3];
      auto it = halfEdges.find(edgeKey(b, a));
      if (it == halfEdges.end()) continue;
      int t2 = it->second / 3;
      unite(t * 3 + i, t2 * 3 + cornerIn(t2, a));
      unite(t * 3 + (i + 1) % 3, t2 * 3 + cornerIn(t2, b));
    }
  const PatchReport& rep = layout.patches[patch];
  for (int k = 0; k < int(rep.loop.size()); ++k) {
    loopWedge_.push_back(wedge(rep.loopTriangle[k], cornerIn(rep.loopTriangle[k], rep.loop[k])));
    uv_[loopWedge_.back()] = boundaryUv(k);
  }
  if (!map) return;
  if (guide && guide->faceDirections) alignToField(*guide, halfEdges);
  else mapInterior();
  indexTriangles();
}

PatchMap::PatchMap(const PatchLayout& layout, int patch, const std::vector<int>& triangles,
                   const std::unordered_map<std::uint64_t, int>& halfEdges, const std::function<Vec2(int)>& boundaryUv,
                   const PatchGuide* guide)
    : PatchMap(layout, patch, triangles, halfEdges, boundaryUv, guide, true) {}

FieldAlignedProblem PatchMap::alignedProblem(const PatchLayout& layout, int patch, const std::vector<int>& triangles,
                                             const std::unordered_map<std::uint64_t, int>& halfEdges,
                                             const std::function<Vec2(int)>& boundaryUv, const PatchGuide& guide,
                                             std::vector<int>& loopWedges) {
  const PatchMap shell(layout, patch, triangles, halfEdges, boundaryUv, &guide, false);
  std::unordered_map<int, int> index;
  std::vector<int> wedgeOf;
  FieldAlignedProblem pb = shell.problem(guide, halfEdges, index, wedgeOf);
  loopWedges.clear();
  for (const int x : shell.loopWedge_) loopWedges.push_back(index.at(x));
  return pb;
}

Vec2 PatchMap::loopImage(int k) const { return uv_.at(loopWedge_.at(k)); }

FieldAlignedProblem PatchMap::problem(const PatchGuide& guide, const std::unordered_map<std::uint64_t, int>& halfEdges,
                                      std::unordered_map<int, int>& index, std::vector<int>& wedgeOf) const {
  FieldAlignedProblem pb;
  std::unordered_map<int, int> local;  // layout triangle -> its number in pb
  for (int k = 0; k < int(triangles_.size()); ++k) local[triangles_[k]] = k;
  for (int t : triangles_) {
    std::array<int, 3> w;
    std::array<Vec3, 3> p;
    for (int c = 0; c < 3; ++c) {
      const int x = wedge(t, c);
      auto it = index.find(x);
      if (it == index.end()) {
        it = index.emplace(x, int(wedgeOf.size())).first;
        wedgeOf.push_back(x);
        auto known = uv_.find(x);  // the boundary's; inside, the solve needs no start
        pb.start.push_back(known != uv_.end() ? known->second : Vec2::Zero());
        pb.constraint.push_back(FieldAlignedProblem::Free);
      }
      w[c] = it->second;
      p[c] = layout_.positions[layout_.triangles[t][c]];
    }
    pb.triangles.push_back(w);
    pb.corners.push_back(p);
    const int face = layout_.originalFace[t];
    pb.direction.push_back(face >= 0 && face < int(guide.faceDirections->size()) ? (*guide.faceDirections)[face] : Vec3::Zero());
    std::array<int, 3> nb{-1, -1, -1};
    for (int i = 0; i < 3; ++i) {
      if (layout_.edgeCurve[t][i] != -1) continue;
      auto it = halfEdges.find(edgeKey(layout_.triangles[t][(i + 1) % 3], layout_.triangles[t][i]));
      if (it == halfEdges.end()) continue;
      auto jt = local.find(it->second / 3);
      if (jt != local.end()) nb[i] = jt->second;
    }
    pb.neighbours.push_back(nb);
  }
  for (const int x : loopWedge_) pb.constraint[index.at(x)] = FieldAlignedProblem::Fixed;
  for (int k = 0; k < int(guide.loopConstraint.size()) && k < int(loopWedge_.size()); ++k)
    pb.constraint[index.at(loopWedge_[k])] = guide.loopConstraint[k];
  // A wedge the loop meets twice (a cut) is fixed.
  std::unordered_map<int, int> seen;
  for (const int x : loopWedge_)
    if (++seen[x] > 1) pb.constraint[index.at(x)] = FieldAlignedProblem::Fixed;
  return pb;
}

void PatchMap::alignToField(const PatchGuide& guide, const std::unordered_map<std::uint64_t, int>& halfEdges) {
  std::unordered_map<int, int> index;  // wedge -> its number in pb
  std::vector<int> wedgeOf;
  const FieldAlignedProblem pb = problem(guide, halfEdges, index, wedgeOf);
  const FieldAlignedResult aligned = solveFieldAlignedMap(pb);
  if (aligned.solved && foldedTriangles(pb.triangles, aligned.uv, 0) == 0) {
    guided_ = GuidedMap::Aligned;
    for (std::size_t w = 0; w < wedgeOf.size(); ++w) uv_[wedgeOf[w]] = aligned.uv[w];
    return;
  }
  // It folds (or failed): the mean-value map, and the aligned one blended back towards it
  // until it folds no more than the mean-value map itself (which rounding can leave on slivers).
  mapInterior();
  guided_ = GuidedMap::MeanValue;
  if (!aligned.solved) return;
  std::vector<Vec2> meanValue(wedgeOf.size());
  for (std::size_t w = 0; w < wedgeOf.size(); ++w) meanValue[w] = uv_.at(wedgeOf[w]);
  const int before = foldedTriangles(pb.triangles, meanValue, 0);
  std::vector<Vec2> uv(wedgeOf.size());
  for (double share : {1.0, 0.5, 0.25, 0.125}) {
    for (std::size_t w = 0; w < uv.size(); ++w) uv[w] = share * aligned.uv[w] + (1 - share) * meanValue[w];
    if (foldedTriangles(pb.triangles, uv, 0) <= before) {
      guided_ = share == 1.0 ? GuidedMap::Aligned : GuidedMap::Blended;
      for (std::size_t w = 0; w < uv.size(); ++w) uv_[wedgeOf[w]] = uv[w];
      return;
    }
  }
}

void PatchMap::mapInterior() {
  // Interior wedges: mean-value weights, w_ab = (tan(α/2) + tan(β/2)) / |ab| summed per triangle.
  std::unordered_map<int, int> interior;
  std::vector<int> interiorWedge;
  for (int t : triangles_)
    for (int c = 0; c < 3; ++c) {
      int w = wedge(t, c);
      if (!uv_.count(w) && !interior.count(w)) {
        interior[w] = int(interiorWedge.size());
        interiorWedge.push_back(w);
      }
    }
  const int ni = int(interiorWedge.size());
  if (ni == 0) return;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
  std::vector<double> diagonal(ni, 0);
  for (int t : triangles_) {
    const auto& tri = layout_.triangles[t];
    for (int c = 0; c < 3; ++c) {
      auto it = interior.find(wedge(t, c));
      if (it == interior.end()) continue;
      const Vec3& pa = layout_.positions[tri[c]];
      for (int other : {1, 2}) {
        int cb = (c + other) % 3, cd = (c + 3 - other) % 3;
        Vec3 eb = layout_.positions[tri[cb]] - pa, ed = layout_.positions[tri[cd]] - pa;
        double angle = std::atan2(eb.cross(ed).norm(), eb.dot(ed));
        double w = std::tan(angle / 2) / std::max(eb.norm(), 1e-300);
        diagonal[it->second] += w;
        int wb = wedge(t, cb);
        auto jt = interior.find(wb);
        if (jt != interior.end()) entries.emplace_back(it->second, jt->second, -w);
        else rhs.row(it->second) += w * uv_.at(wb).transpose();
      }
    }
  }
  for (int i = 0; i < ni; ++i) entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<double> A(ni, ni);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(A);
  if (solver.info() != Eigen::Success) throw std::runtime_error("patch " + std::to_string(patch_) + ": its mapping failed");
  Eigen::MatrixXd uv = solver.solve(rhs);
  for (int i = 0; i < ni; ++i) uv_[interiorWedge[i]] = Vec2(uv(i, 0), uv(i, 1));
}

void PatchMap::indexTriangles() {
  // The triangles' images, once, and a grid over their bounding box listing each triangle in
  // the cells its bounding box covers (about one triangle per cell): a query looks at the few
  // triangles of its cell instead of all of the patch's.
  const int n = int(triangles_.size());
  corners_.resize(n);
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) {
      corners_[k][c] = uv_.at(wedge(triangles_[k], c));
      lo = lo.cwiseMin(corners_[k][c]);
      hi = hi.cwiseMax(corners_[k][c]);
    }
  if (n == 0 || !(hi.x() >= lo.x()) || !(hi.y() >= lo.y())) return;
  gridLow_ = lo;
  gridHigh_ = hi;
  const int side = std::clamp(int(std::sqrt(double(n))), 1, 1024);
  gridN_ = side;
  gridStep_ = Vec2(std::max(hi.x() - lo.x(), 1e-12) / side, std::max(hi.y() - lo.y(), 1e-12) / side);
  std::vector<std::vector<int>> cells(side * side);
  for (int k = 0; k < n; ++k) {
    Vec2 a = corners_[k][0].cwiseMin(corners_[k][1]).cwiseMin(corners_[k][2]);
    Vec2 b = corners_[k][0].cwiseMax(corners_[k][1]).cwiseMax(corners_[k][2]);
    const int x0 = cellCoordinate(a.x(), 0), x1 = cellCoordinate(b.x(), 0);
    const int y0 = cellCoordinate(a.y(), 1), y1 = cellCoordinate(b.y(), 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells[y * side + x].push_back(k);
  }
  cellBegin_.assign(1, 0);
  for (const auto& c : cells) {
    cellTriangles_.insert(cellTriangles_.end(), c.begin(), c.end());
    cellBegin_.push_back(int(cellTriangles_.size()));
  }
}

int PatchMap::cellCoordinate(double value, int axis) const {
  const double t = std::floor((value - gridLow_[axis]) / gridStep_[axis]);
  if (!(t >= 0)) return 0;
  return t >= gridN_ ? gridN_ - 1 : int(t);
}

Vec3 PatchMap::pointAt(const Vec2& x) const {
  int best = -1;
  double bestMin = -1e300, b0 = 0, b1 = 0, b2 = 0;
  // Barycentric coordinates of x in triangle k (of triangles_); false if it is degenerate.
  auto locate = [&](int k, double& l0, double& l1, double& l2) {
    const Vec2 &A = corners_[k][0], &B = corners_[k][1], &C = corners_[k][2];
    const double area = cross2(B - A, C - A);
    if (std::abs(area) < 1e-300) return false;
    l0 = cross2(B - x, C - x) / area, l1 = cross2(C - x, A - x) / area, l2 = 1 - l0 - l1;
    return true;
  };
  // The surface point at barycentric coordinates (l0, l1, l2) of layout triangle t.
  auto pointOn = [&](int t, double l0, double l1, double l2) {
    const auto& tri = layout_.triangles[t];
    return Vec3(l0 * layout_.positions[tri[0]] + l1 * layout_.positions[tri[1]] + l2 * layout_.positions[tri[2]]);
  };
  // A triangle holding x holds it in its bounding box, so it is listed in x's cell, where
  // triangles are in the patch's order: the first holding x is the one a scan of all finds.
  if (gridN_ > 0 && x.x() >= gridLow_.x() && x.y() >= gridLow_.y() && x.x() <= gridHigh_.x() && x.y() <= gridHigh_.y()) {
    const int cell = cellCoordinate(x.y(), 1) * gridN_ + cellCoordinate(x.x(), 0);
    for (int i = cellBegin_[cell]; i < cellBegin_[cell + 1]; ++i) {
      double l0, l1, l2;
      const int k = cellTriangles_[i];
      if (!locate(k, l0, l1, l2) || !(std::min({l0, l1, l2}) >= 0)) continue;  // NaN too, as the scan
      return pointOn(triangles_[k], l0, l1, l2);
    }
  }
  // Outside every triangle (or on none, by rounding): the scan finds the nearest.
  for (int k = 0; k < int(triangles_.size()); ++k) {
    double l0, l1, l2;
    if (!locate(k, l0, l1, l2)) continue;
    double mn = std::min({l0, l1, l2});
    if (mn > bestMin) bestMin = mn, best = triangles_[k], b0 = l0, b1 = l1, b2 = l2;
    if (mn >= 0) break;
  }
  if (best < 0) throw std::runtime_error("patch " + std::to_string(patch_) + ": its map has no usable triangle");
  if (bestMin < 0) {
    // Outside every mapped triangle: the nearest one, barycentric coordinates clamped.
    if (bestMin < -1e-6) ++outside_;
    b0 = std::max(0.0, b0), b1 = std::max(0.0, b1), b2 = std::max(0.0, b2);
    const double sum = b0 + b1 + b2;
    b0 /= sum, b1 /= sum, b2 /= sum;
  }
  return pointOn(best, b0, b1, b2);
}

}  // namespace fcql
