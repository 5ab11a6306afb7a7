// Auxiliary points on the edges of the mesh (paper §3.2).
//
// The auxiliary points ("samples") split each edge into segments that each subtend an angle
// below φ at the vertex opposite the edge, in each incident triangle, so that the density of
// points follows the angular resolution a path leaving a point sees. They are placed by a
// greedy walk along the edge, each step as long as both opposite vertices allow, then spread
// so that the last segment is not a sliver: where the vertex sees the edge obliquely the
// points are sparser than equal steps would make them (equal steps need about a third more
// points on typical scans for the same bound). At least one point per edge; uniform steps,
// capped, for needle triangles.
//
// Every edge has a canonical orientation: the one it has in its first face (side 0); in the
// face on the other side (side 1) it runs the other way. A sample's parameter λ ∈ (0, 1) is
// measured along the canonical orientation.
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <vector>

namespace fcql {

struct EdgeSampling {
  std::vector<int> firstSample;   ///< per edge id: id of its first sample
  std::vector<int> sampleCount;   ///< per edge id: number of samples (segments − 1)
  std::vector<std::array<int, 2>> edgeFace;   ///< per edge id: face on side 0 and 1 (−1 = border)
  std::vector<std::array<int, 2>> edgeLocal;  ///< per edge id: local edge index in each face
  std::vector<int> sampleEdge;    ///< per sample: its edge id
  std::vector<double> sampleParam;  ///< per sample: λ along the canonical orientation
  std::vector<Vec3> samplePosition; ///< per sample

  int numSamples() const { return int(sampleEdge.size()); }
  /// Side (0 or 1) of face f with respect to edge id e.
  int sideOf(int e, int f) const { return edgeFace[e][0] == f ? 0 : 1; }
  /// Position of a sample along local edge i of face f, from corner i (0) to corner i+1 (1).
  double paramInFace(int sample, int f) const {
    int e = sampleEdge[sample];
    return sideOf(e, f) == 0 ? sampleParam[sample] : 1.0 - sampleParam[sample];
  }
};

/// Samples every edge with angular resolution `phiRadians`; at most `maxSegments` segments
/// per edge (needle triangles would otherwise ask for hundreds). The edges are sampled on
/// `threads` worker threads (0: all hardware threads); the result does not depend on it.
EdgeSampling sampleEdges(const SurfaceMesh& mesh, double phiRadians, int maxSegments = 48, int threads = 1);

}  // namespace fcql
