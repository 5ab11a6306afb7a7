// A path traced in graph G: a field-coherent polyline with its joints on mesh edges.
#pragma once

#include "mesh/surface_mesh.h"

#include <vector>

namespace fcql {

struct PathPoint {
  enum Kind { Vertex, Sample, Crossing };
  Kind kind = Sample;
  int id = -1;  ///< vertex id, sample id, or the barrier separatrix for a crossing
  Vec3 position;
};

/// A straight piece of a path inside one triangle, following direction `direction` of the
/// triangle's cross. Its chord runs from perimeter coordinate `from` to `to` (see chordCoordinate).
struct PathSegment {
  int face = -1;
  int direction = 0;
  double from = 0, to = 0;
};

struct TracedPath {
  enum End { Sink, Border, Barrier };
  int sourcePort = -1;
  End end = Sink;
  int sinkPort = -1;     ///< for End::Sink
  int barrier = -1;      ///< for End::Barrier: id of the separatrix reached
  double length = 0;     ///< anisotropic length γ (Eq. 1)
  std::vector<PathPoint> points;      ///< points.size() == segments.size() + 1
  std::vector<PathSegment> segments;

  double euclideanLength() const {
    double l = 0;
    for (std::size_t i = 1; i < points.size(); ++i) l += (points[i].position - points[i - 1].position).norm();
    return l;
  }
};

/// Coordinates along the boundary of a triangle, in [0, 3): corner c is at c, a point at
/// fraction u of local edge i (from corner i to corner i+1) is at i + u. Two chords of a
/// triangle cross inside it iff their endpoints interleave along the boundary.
inline double cornerCoordinate(int corner) { return double(corner); }
inline double edgeCoordinate(int localEdge, double u) { return localEdge + u; }

enum class ChordRelation { Disjoint, Crossing, Touching, SameChord };

/// How two chords of the same triangle meet. Touching: they share exactly one endpoint that
/// is not a corner (two paths through the same auxiliary point). Chords meeting only at a
/// corner (a singular vertex) are Disjoint.
ChordRelation relateChords(double a1, double b1, double a2, double b2);

}  // namespace fcql
