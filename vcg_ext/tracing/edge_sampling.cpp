#include "tracing/edge_sampling.h"

#include <algorithm>
#include <cmath>

namespace fcql {
namespace {

double angleAt(const Vec3& apex, const Vec3& a, const Vec3& b) {
  Vec3 u = a - apex, v = b - apex;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// Smallest segment count so that each of the n equal segments of [a, b] subtends less than
/// phi at `apex`.
int segmentsFor(const Vec3& a, const Vec3& b, const Vec3& apex, double phi, int maxSegments) {
  int n = std::max(1, int(std::ceil(angleAt(apex, a, b) / phi)));
  for (; n < maxSegments; ++n) {
    bool ok = true;
    for (int i = 0; i < n && ok; ++i)
      ok = angleAt(apex, a + (b - a) * (double(i) / n), a + (b - a) * (double(i + 1) / n)) < phi;
    if (ok) return n;
  }
  return maxSegments;
}

}  // namespace

EdgeSampling sampleEdges(const SurfaceMesh& mesh, double phiRadians, int maxSegments) {
  const int ne = mesh.numEdges();
  EdgeSampling s;
  s.firstSample.assign(ne, 0);
  s.sampleCount.assign(ne, 0);
  s.edgeFace.assign(ne, {-1, -1});
  s.edgeLocal.assign(ne, {-1, -1});
  std::vector<int> segments(ne, 2);
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      int e = mesh.edgeId(f, i);
      int side = s.edgeFace[e][0] < 0 ? 0 : 1;
      s.edgeFace[e][side] = f;
      s.edgeLocal[e][side] = i;
      const Vec3& a = mesh.position(mesh.vertex(f, i));
      const Vec3& b = mesh.position(mesh.vertex(f, (i + 1) % 3));
      const Vec3& apex = mesh.position(mesh.vertex(f, (i + 2) % 3));
      // At least two segments: every edge carries a point that paths can cross it at.
      segments[e] = std::max(segments[e], segmentsFor(a, b, apex, phiRadians, maxSegments));
    }
  int next = 0;
  for (int e = 0; e < ne; ++e) {
    s.firstSample[e] = next;
    s.sampleCount[e] = segments[e] - 1;
    next += segments[e] - 1;
  }
  s.sampleEdge.resize(next);
  s.sampleParam.resize(next);
  s.samplePosition.resize(next);
  for (int e = 0; e < ne; ++e) {
    int f = s.edgeFace[e][0], i = s.edgeLocal[e][0];
    const Vec3& a = mesh.position(mesh.vertex(f, i));
    const Vec3& b = mesh.position(mesh.vertex(f, (i + 1) % 3));
    for (int k = 0; k < s.sampleCount[e]; ++k) {
      int id = s.firstSample[e] + k;
      double lambda = double(k + 1) / segments[e];
      s.sampleEdge[id] = e;
      s.sampleParam[id] = lambda;
      s.samplePosition[id] = a + (b - a) * lambda;
    }
  }
  return s;
}

}  // namespace fcql
