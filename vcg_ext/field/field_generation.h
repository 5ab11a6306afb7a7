// Smooth, curvature-aligned cross field generation (DESIGN.md §3).
//
// The field is computed as a per-face 4-RoSy in complex form (z_f = e^{4iθ_f} in the face
// frame) minimising a smoothness energy built with the discrete Levi-Civita connection across
// edges, plus a soft alignment to the principal curvature directions weighted by their
// anisotropy, with hard alignment of faces incident to sharp edges (dihedral angle above a
// threshold) and to border edges. One sparse Hermitian solve (Eigen), then normalisation.
#pragma once

#include "field/cross_field.h"

namespace fcql {

struct FieldGenerationOptions {
  /// Edges whose dihedral angle (angle between the normals) exceeds this are sharp: the field
  /// is constrained to follow them. 0..180; 180 disables sharp-edge alignment.
  double sharpAngleDeg = 35.0;
  /// Align the field to border edges.
  bool alignToBorders = true;
  /// Weight of the soft curvature alignment relative to smoothness (0 = smoothest field).
  double curvatureWeight = -1;  ///< negative: the built-in default
};

struct FieldGenerationReport {
  int sharpEdges = 0;        ///< number of edges detected as sharp
  int constrainedFaces = 0;  ///< faces with a hard alignment constraint
};

/// Per edge id (SurfaceMesh::edgeId): 1 if the dihedral angle exceeds `sharpAngleDeg`.
std::vector<char> detectSharpEdges(const SurfaceMesh& mesh, double sharpAngleDeg);

/// Throws FieldError if an option is out of range.
CrossField generateCrossField(const SurfaceMesh& mesh, const FieldGenerationOptions& options = {},
                              FieldGenerationReport* report = nullptr);

}  // namespace fcql
