#include "metrics/quad_quality.h"

#include "util/math_constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <thread>

namespace fcql {

namespace {

/// Angle (−π..π) of tangent vector d, projected onto face f, from the field's first direction
/// u[f]; false if d has no component in the face's plane.
bool angleFromField(const SurfaceMesh& surface, const CrossField& field, int f, const Vec3& d, double& angle) {
  const Vec3& n = surface.faceNormal(f);
  const Vec3 t = d - n * n.dot(d);
  if (!(t.norm() > 0)) return false;
  const Vec3& u = field.u[f];
  angle = std::atan2(t.dot(n.cross(u)), t.dot(u));
  return true;
}

/// Angle (0..π/4) between tangent vector d, projected onto face f, and the nearest direction
/// of the cross of f (π/4 if d has no component in the face's plane).
double angleToCross(const SurfaceMesh& surface, const CrossField& field, int f, const Vec3& d) {
  double a;
  if (!angleFromField(surface, field, f, d, a)) return kPi / 4;
  a = std::fmod(a + 4 * kPi, kPi / 2);  // 0..π/2
  return std::min(a, kPi / 2 - a);
}

/// The two directions of quad q: the vectors joining the midpoints of its opposite edges
/// (doubled, which changes no angle).
std::array<Vec3, 2> quadDirections(const QuadMesh& quads, int q) {
  const auto& P = quads.positions;
  const auto& f = quads.quads[q];
  return {(P[f[1]] + P[f[2]]) - (P[f[0]] + P[f[3]]), (P[f[2]] + P[f[3]]) - (P[f[0]] + P[f[1]])};
}

/// Percentage of the faces of `surface` misaligned as the paper's Table 2 counts them (see
/// the header).
double misalignedFacesPercent(const QuadMesh& quads, const SurfaceMesh& surface, const CrossField& field,
                              double thresholdRad) {
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(2 * std::size_t(quads.numQuads()));
  for (const auto& q : quads.quads) {
    triangles.push_back({q[0], q[1], q[2]});
    triangles.push_back({q[0], q[2], q[3]});
  }
  const ClosestPointIndex quadIndex(quads.positions, std::move(triangles));
  int misaligned = 0, measured = 0;
  for (int f = 0; f < surface.numFaces(); ++f) {
    const ClosestPoint cp = quadIndex.closest(surface.faceCentroid(f));
    if (cp.triangle < 0) continue;
    double s = 0, c = 0;
    for (const Vec3& d : quadDirections(quads, cp.triangle / 2)) {
      double a;
      if (angleFromField(surface, field, f, d, a)) s += std::sin(4 * a), c += std::cos(4 * a);
    }
    ++measured;
    const double deviation = (s == 0 && c == 0) ? kPi / 4 : std::abs(std::atan2(s, c)) / 4;
    if (deviation > thresholdRad) ++misaligned;
  }
  return measured > 0 ? 100.0 * misaligned / measured : 0;
}

/// Radius of the smallest disk around the vertices of triangle (a, b, c) that covers it: the
/// largest distance from a point of the triangle to its nearest vertex (the circumradius when
/// the triangle has no obtuse angle; else reached on the longest edge, where it meets the
/// perpendicular bisectors of the two shorter ones).
double coverRadius(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  // Name the corners so that the longest edge is uv, w opposite it.
  double uv = ab, uw = ca, vw = bc;
  if (bc >= ab && bc >= ca) uv = bc, uw = ab, vw = ca;
  else if (ca >= ab && ca >= bc) uv = ca, uw = bc, vw = ab;
  if (!(uv > 0)) return 0;
  if (uw * uw + vw * vw >= uv * uv) {  // no obtuse angle: the circumradius
    const double area2 = (b - a).cross(c - a).norm();  // twice the area
    if (!(area2 > 0)) return uv / 2;
    return ab * bc * ca / (2 * area2);
  }
  // Obtuse at w: angles U (at u) and V (at v) are acute; the bisector of uw meets uv at
  // distance |uw| / (2 cos U) from u (and w), likewise for vw.
  const double cosU = (uv * uv + uw * uw - vw * vw) / (2 * uv * uw);
  const double cosV = (uv * uv + vw * vw - uw * uw) / (2 * uv * vw);
  double r = uv / 2;
  if (uw > 0 && cosU > 0) r = std::max(r, std::min(uv, uw / (2 * cosU)));
  if (vw > 0 && cosV > 0) r = std::max(r, std::min(uv, vw / (2 * cosV)));
  return r;
}

/// Once a distance found exceeds the limit, measureOneWay seeks the bound to within this
/// fraction of the excess only: the pass fails whatever the precision, and the bound then only
/// sets the next pass's size (its square root does, up to 3.24 times the limit; beyond, the
/// size is halved) and tells whether that pass got closer. Relative to the excess, not to
/// the distance: a pass a little over the limit keeps the resolution's precision, as its
/// next size depends on it most (5% of the distance made rockerarm's refined pass 20% finer).
constexpr double kFailedPassPrecision = 0.05;

/// One way of the two-sided distance: the triangles `triangles` over `positions` against
/// `other`. Each triangle's vertices are measured (once per vertex), then the triangle is cut
/// into four at its edges' midpoints, recursively, wherever its bound (largest distance at its
/// vertices + its cover radius: the distance to a surface grows at most as fast as one moves)
/// exceeds the threshold, max(limit, the largest distance found so far), and its cover radius
/// is above `resolution`. Every point of a triangle is within its bound of `other`.
void measureOneWay(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles,
                   const ClosestPointIndex& other, double limit, double resolution, SurfaceDeviation& d) {
  std::vector<double> at(positions.size(), -1);
  auto far = [&](const Vec3& p, double distance) {
    if (limit > 0 && distance > limit) d.farPoints.push_back(p);
  };
  for (const auto& t : triangles)
    for (int v : t)
      if (at[v] < 0) {
        at[v] = other.closest(positions[v]).distance;
        d.distance = std::max(d.distance, at[v]);
        far(positions[v], at[v]);
      }
  struct Piece {
    Vec3 p[3];
    double dist[3];
  };
  std::vector<Piece> stack;
  for (const auto& t : triangles) {
    stack.push_back({{positions[t[0]], positions[t[1]], positions[t[2]]}, {at[t[0]], at[t[1]], at[t[2]]}});
    while (!stack.empty()) {
      const Piece piece = stack.back();
      stack.pop_back();
      const double worst = std::max({piece.dist[0], piece.dist[1], piece.dist[2]});
      const double radius = coverRadius(piece.p[0], piece.p[1], piece.p[2]);
      const double bound = worst + radius;
      // Once the largest distance found exceeds the limit, the bound is sought to within
      // kFailedPassPrecision of the excess. Cutting to the resolution (2% of the limit)
      // wherever the distance is above the limit took millions of samples a measurement on a
      // coarse pass (26 s of the rounded box's run at --scale 0.3, 7 s now), and a tiny limit
      // had every pass cut that finely over most of the surface.
      const double finest =
          limit > 0 && d.distance > limit ? std::max(resolution, kFailedPassPrecision * (d.distance - limit)) : resolution;
      if (bound <= std::max(limit, d.distance) || radius <= finest) {
        d.bound = std::max(d.bound, bound);
        if (limit > 0 && bound > limit && worst <= limit) {
          // Undecided at the finest resolution: counts as too far, where its worst point is.
          const int k = int(std::max_element(piece.dist, piece.dist + 3) - piece.dist);
          d.farPoints.push_back(piece.p[k]);
        }
        continue;
      }
      Vec3 m[3];
      double md[3];
      for (int i = 0; i < 3; ++i) {
        m[i] = (piece.p[i] + piece.p[(i + 1) % 3]) / 2;
        md[i] = other.closest(m[i]).distance;
        d.distance = std::max(d.distance, md[i]);
        far(m[i], md[i]);
      }
      stack.push_back({{piece.p[0], m[0], m[2]}, {piece.dist[0], md[0], md[2]}});
      stack.push_back({{m[0], piece.p[1], m[1]}, {md[0], piece.dist[1], md[1]}});
      stack.push_back({{m[2], m[1], piece.p[2]}, {md[2], md[1], piece.dist[2]}});
      stack.push_back({{m[0], m[1], m[2]}, {md[0], md[1], md[2]}});
    }
  }
}

}  // namespace

std::vector<std::array<int, 3>> quadTriangles(const QuadMesh& quads) {
  const auto& P = quads.positions;
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(2 * quads.quads.size());
  for (const auto& f : quads.quads) {
    if ((P[f[2]] - P[f[0]]).squaredNorm() <= (P[f[3]] - P[f[1]]).squaredNorm()) {
      triangles.push_back({f[0], f[1], f[2]});
      triangles.push_back({f[0], f[2], f[3]});
    } else {
      triangles.push_back({f[0], f[1], f[3]});
      triangles.push_back({f[1], f[2], f[3]});
    }
  }
  return triangles;
}

SurfaceDeviation measureDeviation(const QuadMesh& quads, const ClosestPointIndex& surfaceIndex, double limit,
                                  double resolution) {
  SurfaceDeviation d;
  if (quads.quads.empty()) {
    d.distance = d.bound = std::numeric_limits<double>::infinity();
    return d;
  }
  const std::vector<std::array<int, 3>> triangles = quadTriangles(quads);
  const ClosestPointIndex quadIndex(quads.positions, triangles);
  std::vector<Vec3> surfacePositions;
  std::vector<std::array<int, 3>> surfaceTriangles;
  surfaceTriangles.reserve(surfaceIndex.numTriangles());
  std::vector<int> renumber;
  for (int t = 0; t < surfaceIndex.numTriangles(); ++t) {
    std::array<int, 3> tri = surfaceIndex.triangle(t);
    for (int& v : tri) {
      if (v >= int(renumber.size())) renumber.resize(v + 1, -1);
      if (renumber[v] < 0) renumber[v] = int(surfacePositions.size()), surfacePositions.push_back(surfaceIndex.position(v));
      v = renumber[v];
    }
    surfaceTriangles.push_back(tri);
  }
  // The two ways on two threads where there are two, each with its own result, then merged.
  SurfaceDeviation other;
  std::thread second([&] { measureOneWay(surfacePositions, surfaceTriangles, quadIndex, limit, resolution, other); });
  measureOneWay(quads.positions, triangles, surfaceIndex, limit, resolution, d);
  second.join();
  d.distance = std::max(d.distance, other.distance);
  d.bound = std::max({d.bound, other.bound, d.distance});
  d.farPoints.insert(d.farPoints.end(), other.farPoints.begin(), other.farPoints.end());
  return d;
}

QuadJacobian::QuadJacobian(const QuadMesh& mesh, std::vector<Vec3> referenceNormals)
    : QuadJacobian(mesh, true) {
  referenceNormals_ = std::move(referenceNormals);
}

QuadJacobian::QuadJacobian(const QuadMesh& mesh, bool surfaceNormals)
    : mesh_(mesh), quadsOf_(mesh.positions.size()), surfaceNormals_(surfaceNormals) {
  for (int q = 0; q < mesh.numQuads(); ++q)
    for (int v : mesh.quads[q]) quadsOf_[v].push_back(q);
}

Vec3 QuadJacobian::quadNormal(int q) const {
  const auto& P = mesh_.positions;
  const auto& f = mesh_.quads[q];
  const Vec3 n = (P[f[2]] - P[f[0]]).cross(P[f[3]] - P[f[1]]);
  const double l = n.norm();
  return l > 0 ? Vec3(n / l) : Vec3(Vec3::Zero());
}

Vec3 QuadJacobian::normalFromKept(int v) const {
  Vec3 sum = Vec3::Zero();
  for (int q : quadsOf_[v]) sum += quadNormal_[q];
  const double l = sum.norm();
  return l > 0 ? Vec3(sum / l) : Vec3(Vec3::Zero());
}

void QuadJacobian::track() const {
  quadNormal_.resize(mesh_.quads.size());
  for (int q = 0; q < int(quadNormal_.size()); ++q) quadNormal_[q] = quadNormal(q);
  normalCache_.resize(mesh_.positions.size());
  for (int v = 0; v < int(normalCache_.size()); ++v) normalCache_[v] = normalFromKept(v);
  stamp_.assign(mesh_.positions.size(), 0);  // the per-call cache of values() starts again afterwards
  tracking_ = true;
}

void QuadJacobian::moved(int v) const {
  if (!tracking_) return;
  for (int q : quadsOf_[v]) quadNormal_[q] = quadNormal(q);
  for (int q : quadsOf_[v])
    for (int w : mesh_.quads[q]) normalCache_[w] = normalFromKept(w);
}

Vec3 QuadJacobian::vertexNormal(int v) const {
  Vec3 sum = Vec3::Zero();
  for (int q : quadsOf_[v]) sum += quadNormal(q);
  const double l = sum.norm();
  return l > 0 ? Vec3(sum / l) : Vec3(Vec3::Zero());
}

template <class Normal>
double QuadJacobian::evaluate(int q, Normal&& normalAt) const {
  const double own = scaledJacobian(mesh_, q);
  if (!surfaceNormals_) return own;
  const auto& f = mesh_.quads[q];
  const auto& P = mesh_.positions;
  double turned = 1;  // the worst corner against the surface normal
  for (int i = 0; i < 4; ++i) {
    const Vec3 e1 = P[f[(i + 1) % 4]] - P[f[i]];
    const Vec3 e2 = P[f[(i + 3) % 4]] - P[f[i]];
    const double l = e1.norm() * e2.norm();
    if (!(l > 0)) return -1;
    const Vec3& n = referenceNormals_.empty() ? normalAt(f[i]) : referenceNormals_[q];
    if (!n.isZero()) turned = std::min(turned, e1.cross(e2).dot(n) / l);
  }
  return turned > 0 ? own : std::min(own, turned);
}

double QuadJacobian::operator()(int q) const {
  Vec3 n;
  return evaluate(q, [&](int v) -> const Vec3& { return n = vertexNormal(v); });
}

void QuadJacobian::values(const std::vector<int>& quads, std::vector<double>& out) const {
  out.resize(quads.size());
  if (tracking_) {
    for (std::size_t i = 0; i < quads.size(); ++i)
      out[i] = evaluate(quads[i], [&](int v) -> const Vec3& { return normalCache_[v]; });
    return;
  }
  if (normalCache_.size() != mesh_.positions.size()) normalCache_.assign(mesh_.positions.size(), Vec3::Zero()), stamp_.assign(mesh_.positions.size(), 0);
  if (++epoch_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), epoch_ = 1;
  auto normalAt = [&](int v) -> const Vec3& {
    if (stamp_[v] != epoch_) stamp_[v] = epoch_, normalCache_[v] = vertexNormal(v);
    return normalCache_[v];
  };
  out.resize(quads.size());
  for (std::size_t i = 0; i < quads.size(); ++i) out[i] = evaluate(quads[i], normalAt);
}

void QuadJacobian::all(std::vector<double>& out) const {
  // Each quad's unit normal once, then each vertex's normal from them.
  std::vector<Vec3> unitNormal(mesh_.quads.size());
  for (std::size_t q = 0; q < unitNormal.size(); ++q) unitNormal[q] = quadNormal(int(q));
  const std::size_t numVertices = mesh_.positions.size();
  std::vector<Vec3> normal(numVertices, Vec3::Zero());
  for (std::size_t v = 0; v < numVertices; ++v) {
    for (int q : quadsOf_[v]) normal[v] += unitNormal[q];
    const double l = normal[v].norm();
    normal[v] = l > 0 ? Vec3(normal[v] / l) : Vec3(Vec3::Zero());
  }
  out.resize(mesh_.quads.size());
  for (std::size_t q = 0; q < out.size(); ++q)
    out[q] = evaluate(int(q), [&](int v) -> const Vec3& { return normal[v]; });
}

void QuadJacobian::dependents(int v, std::vector<int>& out) const {
  out.clear();
  if (!surfaceNormals_ || !referenceNormals_.empty()) {  // a quad's figure depends on its corners only
    out = quadsOf_[v];
    return;
  }
  for (int q : quadsOf_[v])
    for (int w : mesh_.quads[q]) out.insert(out.end(), quadsOf_[w].begin(), quadsOf_[w].end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void QuadJacobian::dependents(const std::vector<int>& vertices, std::vector<int>& out) const {
  out.clear();
  std::vector<int> one;
  for (int v : vertices) {
    dependents(v, one);
    out.insert(out.end(), one.begin(), one.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

double scaledJacobian(const QuadMesh& mesh, int q) {
  const auto& f = mesh.quads[q];
  const auto& P = mesh.positions;
  Vec3 n = (P[f[2]] - P[f[0]]).cross(P[f[3]] - P[f[1]]);
  if (!(n.norm() > 0)) return -1;
  n.normalize();
  double worst = 1;
  for (int i = 0; i < 4; ++i) {
    const Vec3 e1 = P[f[(i + 1) % 4]] - P[f[i]];
    const Vec3 e2 = P[f[(i + 3) % 4]] - P[f[i]];
    const double l = e1.norm() * e2.norm();
    const double j = l > 0 ? e1.cross(e2).dot(n) / l : -1;
    worst = std::min(worst, j);
  }
  return worst;
}

QuadQuality measureQuadQuality(const QuadMesh& quads, const SurfaceMesh& surface, const CrossField& field,
                               const ClosestPointIndex& surfaceIndex, double deviationLimit, double thresholdRad) {
  QuadQuality r;
  const int nq = quads.numQuads();
  if (nq == 0) return r;
  const auto& P = quads.positions;
  const QuadJacobian jacobian(quads);
  int misaligned = 0;
  double sumAngle = 0, sumJ = 0, minJ = std::numeric_limits<double>::infinity();
  for (int q = 0; q < nq; ++q) {
    const auto& f = quads.quads[q];
    const Vec3 centre = (P[f[0]] + P[f[1]] + P[f[2]] + P[f[3]]) / 4;
    const ClosestPoint cp = surfaceIndex.closest(centre);
    const std::array<Vec3, 2> d = quadDirections(quads, q);
    const double angle = std::max(angleToCross(surface, field, cp.triangle, d[0]),
                                  angleToCross(surface, field, cp.triangle, d[1]));
    sumAngle += angle;
    if (angle > thresholdRad) ++misaligned;
    const double j = jacobian(q);
    sumJ += j;
    minJ = std::min(minJ, j);
    if (j <= 0) ++r.invertedQuads;
  }
  r.misalignedPercent = 100.0 * misaligned / nq;
  r.meanMisalignmentDeg = sumAngle / nq * 180 / kPi;
  r.misalignedFacesPercent = misalignedFacesPercent(quads, surface, field, thresholdRad);
  r.minScaledJacobian = minJ;
  r.meanScaledJacobian = sumJ / nq;

  const double diag = surface.boundingBoxDiagonal();
  const SurfaceDeviation deviation =
      measureDeviation(quads, surfaceIndex, deviationLimit, std::max(0.02 * deviationLimit, 2e-4 * diag));
  r.hausdorff = deviation.distance;
  r.hausdorffBound = deviation.bound;
  r.hausdorffRelative = diag > 0 ? r.hausdorff / diag : 0;
  r.hausdorffBoundRelative = diag > 0 ? r.hausdorffBound / diag : 0;
  return r;
}

}  // namespace fcql
