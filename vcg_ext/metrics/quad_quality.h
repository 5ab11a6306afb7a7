// Quality figures of a quad mesh against the surface and the cross field it was built from
// (paper, Table 2, and the usual mesh-quality measures).
//
// - Misalignment: per quad, its two directions are the vectors joining the midpoints of
//   opposite edges; each is projected onto the input face nearest to the quad's centre and its
//   angle to the nearest direction of that face's cross is taken (0..45°). A quad is misaligned
//   when the larger of its two angles exceeds the threshold (π/16 as in the paper). A sheared
//   quad counts, even with one direction on the field.
// - Misaligned faces, as the paper's Table 2 counts them ("the percentage of faces whose
//   misalignment is over π/16", the deviation between the field and the direction field of
//   the parametrization, up to quarter turns): per face of the input, the cross the quads
//   follow there, fitted to the two directions of the quad over the face's centroid (their
//   angles to the field averaged as four-fold angles, so that a quad sheared by σ fits a cross
//   σ/2 off each), against the face's own cross. Shear counts half as much as above.
// - Scaled Jacobian of a quad: the minimum over its corners of (e1 × e2)·n / (|e1| |e2|), with
//   e1, e2 the edges leaving the corner and n the unit normal of the quad (cross product of its
//   diagonals): 1 for a rectangle, ≤ 0 for a folded or inverted corner. Each corner is also
//   measured against the surface normal there (the mean of the unit normals of the quads around
//   the corner's vertex): a quad turned over against its neighbours (a page folded back, whose
//   corners all agree with its own normal) is negative there, and when a corner is, the lowest
//   of those values is taken. So a quad is folded (≤ 0) when any of its four corners is, by
//   either normal; a quad that is not keeps the figure against its own normal.
// - Hausdorff distance between the quad mesh (each quad as two triangles, split along its
//   shorter diagonal) and the input surface, both ways, sampled densely on both: every
//   triangle's vertices, then its edges' midpoints, recursively cut into four, wherever the
//   triangle could still hold a point farther than the threshold (the largest distance at its
//   vertices plus its cover radius, as the distance to a surface grows no faster than one
//   moves). So besides the largest distance found (a lower bound) the measure gives an upper
//   bound on the true distance, and decides whether it is within a limit.
#pragma once

#include "field/cross_field.h"
#include "mesh/closest_point_index.h"
#include "mesh/quad_mesh.h"
#include "util/math_constants.h"

#include <array>
#include <vector>

namespace fcql {

/// The two-sided distance (see above) between `quads` and the surface `surfaceIndex` indexes.
/// With limit > 0, triangles are cut until their bound is within max(limit, the largest
/// distance found) or their cover radius is at most `resolution` (or 5% of the largest
/// distance found minus the limit, once that is positive: the pass fails whatever the
/// precision, and the bound is then within 5% of the excess); farPoints are the samples farther than
/// limit and the worst point of each triangle left undecided (bound above the limit at the
/// finest resolution). With limit = 0, the largest distance is sought to within
/// `resolution`. Exact where it matters: bound ≤ limit guarantees that every point of either
/// surface is within limit of the other.
struct SurfaceDeviation {
  double distance = 0;  ///< largest distance measured at a sample, either way (≤ the true one)
  double bound = 0;     ///< upper bound on the true distance (≥ distance)
  std::vector<Vec3> farPoints;
};
SurfaceDeviation measureDeviation(const QuadMesh& quads, const ClosestPointIndex& surfaceIndex, double limit,
                                  double resolution);

/// The triangles the distance is measured on: each quad split along its shorter diagonal.
std::vector<std::array<int, 3>> quadTriangles(const QuadMesh& quads);

/// Scaled Jacobian of quad q of `mesh` against its own normal only (see above).
double scaledJacobian(const QuadMesh& mesh, int q);

/// The scaled Jacobian of every quad against its own normal and the surface normal at each
/// corner (see above). Moving a vertex changes the figure of the quads around it and of the
/// quads around its neighbours (their corner normals): `dependents` lists them.
class QuadJacobian {
public:
  /// surfaceNormals = false: against the quads' own normals only (as scaledJacobian).
  explicit QuadJacobian(const QuadMesh& mesh, bool surfaceNormals = true);
  /// Against the quads' own normals and, at every corner, a fixed normal per quad
  /// (`referenceNormals[q]`, e.g. the input surface's there) instead of the corner's: a quad's
  /// figure then depends on its own corners only.
  QuadJacobian(const QuadMesh& mesh, std::vector<Vec3> referenceNormals);
  /// Quad q's scaled Jacobian with the mesh's current positions.
  double operator()(int q) const;
  /// The figures of `quads` (out[i] for quads[i]), each corner normal computed once.
  void values(const std::vector<int>& quads, std::vector<double>& out) const;
  /// The figures of every quad.
  void all(std::vector<double>& out) const;
  /// Surface normal at vertex v (unit, zero if its quads have no area).
  Vec3 vertexNormal(int v) const;
  /// Quads whose figure depends on the position of vertex v, sorted.
  void dependents(int v, std::vector<int>& out) const;
  /// Quads whose figure depends on the position of any of `vertices`, sorted, each once.
  void dependents(const std::vector<int>& vertices, std::vector<int>& out) const;
  const std::vector<int>& quadsAround(int v) const { return quadsOf_[v]; }

  /// Keep the surface normal of every vertex (computed now) until untrack(), for callers that
  /// move one vertex at a time and evaluate the quads around it many times (the untangling and
  /// the fold repair): values() and normals() then read the kept normals instead of computing
  /// them, and a caller that moves vertex v must call moved(v), which updates the normals of
  /// the corners of v's quads (the only ones v changes). Same figures as without, bit for bit.
  void track() const;
  void moved(int v) const;
  void untrack() const { tracking_ = false; }
  /// The kept normals (valid while tracking), indexed by vertex.
  const std::vector<Vec3>& normals() const { return normalCache_; }

private:
  const QuadMesh& mesh_;
  template <class Normal>
  double evaluate(int q, Normal&& normalAt) const;

  std::vector<std::vector<int>> quadsOf_;
  bool surfaceNormals_ = true;
  std::vector<Vec3> referenceNormals_;  ///< per quad, if given
  mutable std::vector<Vec3> normalCache_;  ///< per vertex: all valid while tracking, else where stamp_ == epoch_
  mutable std::vector<unsigned> stamp_;
  mutable unsigned epoch_ = 0;
  mutable bool tracking_ = false;
  mutable std::vector<Vec3> quadNormal_;  ///< per quad, unit, kept while tracking
  /// The unit normal of quad q at the current positions (zero if it has no area).
  Vec3 quadNormal(int q) const;
  /// v's normal from the kept quad normals: the same sum, in the same order, as vertexNormal.
  Vec3 normalFromKept(int v) const;
};

/// Whether moving a vertex spoiled a quad that depends on it: given the quads' figures before
/// and after the move (QuadJacobian::values, same order), one fell from above `floor` to it or
/// below, or from above 0 to 0 or below (folded, also where it was at the floor already).
inline bool spoilsQuads(const std::vector<double>& before, const std::vector<double>& after, double floor) {
  for (std::size_t i = 0; i < before.size() && i < after.size(); ++i)
    if ((before[i] > floor && after[i] <= floor) || (before[i] > 0 && after[i] <= 0)) return true;
  return false;
}

struct QuadQuality {
  double misalignedPercent = 0;     ///< % of quads misaligned by more than the threshold
  double meanMisalignmentDeg = 0;   ///< mean over quads of the larger angle, degrees
  double misalignedFacesPercent = 0; ///< % of input faces misaligned as the paper counts them
  double minScaledJacobian = 0;
  double meanScaledJacobian = 0;
  int invertedQuads = 0;            ///< scaled Jacobian ≤ 0
  double hausdorff = 0;             ///< symmetric, absolute: the largest distance found
  double hausdorffRelative = 0;     ///< hausdorff / bounding-box diagonal of the input
  double hausdorffBound = 0;        ///< upper bound on the true distance (measureDeviation)
  double hausdorffBoundRelative = 0;
};

/// `surfaceIndex` indexes the faces of `surface` (ClosestPointIndex(surface)). The Hausdorff
/// distance is measured as measureDeviation does with `deviationLimit` (absolute; 0: the
/// largest distance to within 2e-4 of the diagonal; else to within 2% of the limit, but no
/// finer than that).
QuadQuality measureQuadQuality(const QuadMesh& quads, const SurfaceMesh& surface, const CrossField& field,
                               const ClosestPointIndex& surfaceIndex, double deviationLimit = 0,
                               double thresholdRad = kPi / 16);

}  // namespace fcql
