#include "tracing/edge_sampling.h"

#include "util/math_constants.h"
#include "util/worker_threads.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace fcql {
namespace {

double angleAt(const Vec3& apex, const Vec3& a, const Vec3& b) {
  Vec3 u = a - apex, v = b - apex;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// Parameter along [a, b] of the point y after x = a + t(b − a) for which [x, y] subtends psi
/// at `apex` (law of sines in the triangle apex, x, y); > 1 when the rest of the edge
/// subtends less.
double stepFrom(const Vec3& a, const Vec3& b, const Vec3& apex, double t, double psi) {
  Vec3 ab = b - a;
  double length = ab.norm();
  Vec3 toApex = apex - (a + ab * t);
  double distance = toApex.norm();
  if (length <= 0 || distance <= 1e-12 * length) return t;  // at the apex (degenerate face)
  double beta = std::acos(std::clamp(toApex.dot(ab) / (distance * length), -1.0, 1.0));
  if (psi + beta >= kPi) return 2.0;
  return t + distance * std::sin(psi) / std::sin(psi + beta) / length;
}

/// Greedy walk from a to b: each step goes as far as it can while subtending at most psi at
/// every apex. Returns the interior points' parameters; empty with *ok = false when more than
/// `maxPoints` would be needed.
std::vector<double> greedyPoints(const Vec3& a, const Vec3& b, const std::vector<Vec3>& apexes, double psi,
                                 int maxPoints, bool* ok) {
  std::vector<double> points;
  double t = 0;
  *ok = true;
  for (;;) {
    double next = 2.0;
    for (const Vec3& apex : apexes) next = std::min(next, stepFrom(a, b, apex, t, psi));
    if (next >= 1.0) return points;
    if (next <= t || int(points.size()) >= maxPoints) {
      *ok = false;
      return {};
    }
    points.push_back(next);
    t = next;
  }
}

/// Equal steps: the smallest count n of equal segments of [a, b] that each subtend less than
/// phi at every apex (at least 2, at most maxSegments); returns the n − 1 interior points.
std::vector<double> uniformPoints(const Vec3& a, const Vec3& b, const std::vector<Vec3>& apexes, double phi,
                                  int maxSegments) {
  int n = 2;
  for (const Vec3& apex : apexes) n = std::max(n, int(std::ceil(angleAt(apex, a, b) / phi)));
  for (; n < maxSegments; ++n) {
    bool ok = true;
    for (int i = 0; i < n && ok; ++i)
      for (const Vec3& apex : apexes)
        ok = ok && angleAt(apex, a + (b - a) * (double(i) / n), a + (b - a) * (double(i + 1) / n)) < phi;
    if (ok) break;
  }
  n = std::min(n, maxSegments);
  std::vector<double> points;
  for (int k = 1; k < n; ++k) points.push_back(double(k) / n);
  return points;
}

/// The parameters of the auxiliary points of edge [a, b] whose opposite vertices are
/// `apexes`: as few as the greedy walk needs for every segment to subtend less than phi at
/// each apex, at least one, spread so that the last segment is not a sliver. Equal steps
/// instead when the walk needs more than maxSegments − 1 points (needle triangles, capped) or
/// would leave two points, or a point and an end, closer than a tenth of the mean spacing:
/// near-coincident points make degenerate pieces when the surface is cut along the paths.
std::vector<double> edgePoints(const Vec3& a, const Vec3& b, const std::vector<Vec3>& apexes, double phi,
                               int maxSegments) {
  const double psi = phi * (1 - 1e-9);  // strictly below phi
  bool ok = false;
  std::vector<double> points = greedyPoints(a, b, apexes, psi, maxSegments - 1, &ok);
  if (!ok) return uniformPoints(a, b, apexes, phi, maxSegments);
  if (points.empty()) return {0.5};  // every edge carries a point paths can cross it at
  // Spread: walk again with the angle that, were angles additive, would make all steps
  // equal; keep it if it needs no more points (each of its steps is still below phi).
  const Vec3* binding = &apexes[0];
  for (const Vec3& apex : apexes)
    if (stepFrom(a, b, apex, points.back(), psi) < stepFrom(a, b, *binding, points.back(), psi)) binding = &apex;
  double rest = angleAt(*binding, a + (b - a) * points.back(), b);
  const double n = double(points.size());
  bool spreadOk = false;
  std::vector<double> spread = greedyPoints(a, b, apexes, (n * psi + rest) / (n + 1), maxSegments - 1, &spreadOk);
  if (spreadOk && spread.size() == points.size()) points = spread;
  double smallestGap = std::min(points.front(), 1.0 - points.back());
  for (std::size_t k = 1; k < points.size(); ++k) smallestGap = std::min(smallestGap, points[k] - points[k - 1]);
  if (smallestGap < 0.1 / (n + 1)) return uniformPoints(a, b, apexes, phi, maxSegments);
  return points;
}

/// Spreads the 10 low bits of x to every third bit.
std::uint32_t spreadBits(std::uint32_t x) {
  x &= 0x3ff;
  x = (x | (x << 16)) & 0x030000ff;
  x = (x | (x << 8)) & 0x0300f00f;
  x = (x | (x << 4)) & 0x030c30c3;
  x = (x | (x << 2)) & 0x09249249;
  return x;
}

/// Edge ids sorted by the Morton code of their midpoints on a 1024³ grid over the bounding box.
std::vector<int> spatialEdgeOrder(const SurfaceMesh& mesh, const EdgeSampling& s) {
  const int ne = mesh.numEdges();
  std::vector<Vec3> mid(ne, Vec3::Zero());
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int e = 0; e < ne; ++e) {
    int f = s.edgeFace[e][0], i = s.edgeLocal[e][0];
    if (f < 0) continue;
    mid[e] = 0.5 * (mesh.position(mesh.vertex(f, i)) + mesh.position(mesh.vertex(f, (i + 1) % 3)));
    lo = lo.cwiseMin(mid[e]);
    hi = hi.cwiseMax(mid[e]);
  }
  std::vector<std::pair<std::uint32_t, int>> keyed(ne);
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  for (int e = 0; e < ne; ++e) {
    std::uint32_t c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = std::uint32_t(std::clamp((mid[e][k] - lo[k]) / extent * 1023.0, 0.0, 1023.0));
    keyed[e] = {spreadBits(c[0]) | (spreadBits(c[1]) << 1) | (spreadBits(c[2]) << 2), e};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> order(ne);
  for (int e = 0; e < ne; ++e) order[e] = keyed[e].second;
  return order;
}

}  // namespace

EdgeSampling sampleEdges(const SurfaceMesh& mesh, double phiRadians, int maxSegments, int threads) {
  const int ne = mesh.numEdges();
  EdgeSampling s;
  s.firstSample.assign(ne, 0);
  s.sampleCount.assign(ne, 0);
  s.edgeFace.assign(ne, {-1, -1});
  s.edgeLocal.assign(ne, {-1, -1});
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      int e = mesh.edgeId(f, i);
      int side = s.edgeFace[e][0] < 0 ? 0 : 1;
      s.edgeFace[e][side] = f;
      s.edgeLocal[e][side] = i;
    }
  std::vector<std::vector<double>> params(ne);
  std::atomic<int> nextEdge{0};
  const int chunk = 1024;
  runOnWorkerThreads(workerThreadCount(threads, ne / chunk + 1), [&](int) {
    std::vector<Vec3> apexes;
    for (int first; (first = nextEdge.fetch_add(chunk)) < ne;)
      for (int e = first; e < std::min(ne, first + chunk); ++e) {
        int f = s.edgeFace[e][0], i = s.edgeLocal[e][0];
        if (f < 0) continue;
        const Vec3& a = mesh.position(mesh.vertex(f, i));
        const Vec3& b = mesh.position(mesh.vertex(f, (i + 1) % 3));
        apexes.clear();
        for (int side = 0; side < 2; ++side) {
          int g = s.edgeFace[e][side];
          if (g >= 0) apexes.push_back(mesh.position(mesh.vertex(g, (s.edgeLocal[e][side] + 2) % 3)));
        }
        params[e] = edgePoints(a, b, apexes, phiRadians, maxSegments);
      }
  });
  // Samples are numbered edge by edge in a spatial order (Morton order of the edges'
  // midpoints), so that samples near each other on the surface are near each other in
  // memory: searches sweep the surface as a front.
  std::vector<int> order = spatialEdgeOrder(mesh, s);
  int next = 0;
  for (int e : order) {
    s.firstSample[e] = next;
    s.sampleCount[e] = int(params[e].size());
    next += int(params[e].size());
  }
  s.sampleEdge.resize(next);
  s.sampleParam.resize(next);
  s.samplePosition.resize(next);
  for (int e = 0; e < ne; ++e) {
    int f = s.edgeFace[e][0], i = s.edgeLocal[e][0];
    if (f < 0) continue;
    const Vec3& a = mesh.position(mesh.vertex(f, i));
    const Vec3& b = mesh.position(mesh.vertex(f, (i + 1) % 3));
    for (int k = 0; k < s.sampleCount[e]; ++k) {
      int id = s.firstSample[e] + k;
      double lambda = params[e][k];
      s.sampleEdge[id] = e;
      s.sampleParam[id] = lambda;
      s.samplePosition[id] = a + (b - a) * lambda;
    }
  }
  return s;
}

}  // namespace fcql
