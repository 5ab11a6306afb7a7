#include "metrics/quad_quality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace fcql {

namespace {

constexpr double kPi = 3.14159265358979323846;

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

/// Calls visit(point, distance) for every point the Hausdorff distance measures (see the
/// header): quad centres, corners and edge midpoints against the surface, each once, then the
/// surface points against the quads.
template <class Visit>
void measureBothWays(const QuadMesh& quads, const ClosestPointIndex& surfaceIndex, const std::vector<Vec3>& surfacePoints,
                     Visit&& visit) {
  const auto& P = quads.positions;
  // Quad mesh → surface: every quad's centre, corners and edge midpoints, each point measured
  // once (a corner is shared by about four quads, an edge by two).
  std::vector<char> corner(P.size(), 0);
  std::vector<std::pair<int, int>> edges;
  edges.reserve(4 * quads.quads.size());
  for (const auto& f : quads.quads) {
    const Vec3 centre = (P[f[0]] + P[f[1]] + P[f[2]] + P[f[3]]) / 4;
    visit(centre, surfaceIndex.closest(centre).distance);
    for (int i = 0; i < 4; ++i) {
      corner[f[i]] = 1;
      edges.push_back(std::minmax(f[i], f[(i + 1) % 4]));
    }
  }
  for (std::size_t v = 0; v < P.size(); ++v)
    if (corner[v]) visit(P[v], surfaceIndex.closest(P[v]).distance);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& e : edges) {
    const Vec3 middle = (P[e.first] + P[e.second]) / 2;
    visit(middle, surfaceIndex.closest(middle).distance);
  }
  // Surface → quad mesh, each quad split along its shorter diagonal.
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
  const ClosestPointIndex quadIndex(P, triangles);
  for (const Vec3& p : surfacePoints) visit(p, quadIndex.closest(p).distance);
}

}  // namespace

double hausdorffDistance(const QuadMesh& quads, const ClosestPointIndex& surfaceIndex,
                         const std::vector<Vec3>& surfacePoints) {
  return measureDeviation(quads, surfaceIndex, surfacePoints, std::numeric_limits<double>::infinity()).distance;
}

SurfaceDeviation measureDeviation(const QuadMesh& quads, const ClosestPointIndex& surfaceIndex,
                                  const std::vector<Vec3>& surfacePoints, double limit) {
  SurfaceDeviation d;
  if (quads.quads.empty()) {
    d.distance = std::numeric_limits<double>::infinity();
    return d;
  }
  measureBothWays(quads, surfaceIndex, surfacePoints, [&](const Vec3& p, double distance) {
    d.distance = std::max(d.distance, distance);
    if (distance > limit) d.farPoints.push_back(p);
  });
  return d;
}

QuadJacobian::QuadJacobian(const QuadMesh& mesh, bool surfaceNormals)
    : mesh_(mesh), quadsOf_(mesh.positions.size()), surfaceNormals_(surfaceNormals) {
  for (int q = 0; q < mesh.numQuads(); ++q)
    for (int v : mesh.quads[q]) quadsOf_[v].push_back(q);
}

Vec3 QuadJacobian::vertexNormal(int v) const {
  const auto& P = mesh_.positions;
  Vec3 sum = Vec3::Zero();
  for (int q : quadsOf_[v]) {
    const auto& f = mesh_.quads[q];
    const Vec3 n = (P[f[2]] - P[f[0]]).cross(P[f[3]] - P[f[1]]);
    const double l = n.norm();
    if (l > 0) sum += n / l;
  }
  const double l = sum.norm();
  return l > 0 ? Vec3(sum / l) : Vec3(Vec3::Zero());
}

double QuadJacobian::operator()(int q) const {
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
    const Vec3 n = vertexNormal(f[i]);
    if (!n.isZero()) turned = std::min(turned, e1.cross(e2).dot(n) / l);
  }
  return turned > 0 ? own : std::min(own, turned);
}

void QuadJacobian::dependents(int v, std::vector<int>& out) const {
  out.clear();
  for (int q : quadsOf_[v])
    for (int w : mesh_.quads[q]) out.insert(out.end(), quadsOf_[w].begin(), quadsOf_[w].end());
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
                               const ClosestPointIndex& surfaceIndex, double thresholdRad) {
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

  std::vector<Vec3> surfacePoints;
  for (int v = 0; v < surface.numVertices(); ++v)
    if (!surface.star(v).empty()) surfacePoints.push_back(surface.position(v));
  for (int f = 0; f < surface.numFaces(); ++f) surfacePoints.push_back(surface.faceCentroid(f));
  r.hausdorff = hausdorffDistance(quads, surfaceIndex, surfacePoints);
  const double diag = surface.boundingBoxDiagonal();
  r.hausdorffRelative = diag > 0 ? r.hausdorff / diag : 0;
  return r;
}

}  // namespace fcql
