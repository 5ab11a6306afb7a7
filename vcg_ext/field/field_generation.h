// Smooth, curvature-aligned cross field generation (DESIGN.md §3).
//
// The field is computed as a per-face 4-RoSy in complex form (z_f = e^{4iθ_f} in the face
// frame) minimising a smoothness energy built with the discrete Levi-Civita connection across
// edges, plus a soft alignment to the principal curvature directions weighted by their
// anisotropy, with hard alignment of faces incident to sharp edges (dihedral angle above a
// threshold) and to border edges. The connection's curvature is spread over a length tied to
// the layout's scale (FieldGenerationOptions::scale), so that noise makes no singularities.
// One sparse Hermitian solve (CHOLMOD), a few normalising refinement steps, then
// normalisation; last, opposite singularities on the two ends of one edge are cancelled, then
// pairs of opposite quarters closer than the scale below (field/singularity_pairs.h). See
// field_generation.cpp for the formulas.
//
// Sharp edges constrain the field only where they form feature lines: runs of sharp edges that
// go on nearly straight for a few edges (or for a tenth of the bounding-box diagonal). Isolated
// or zig-zagging sharp edges, the dihedral noise of scanned and coarse organic meshes, are
// ignored. The result does not change when the mesh is scaled uniformly.
#pragma once

#include "field/cross_field.h"

namespace fcql {

struct FieldGenerationOptions {
  /// Edges whose dihedral angle (angle between the normals) exceeds this are sharp: the field
  /// is constrained to follow them. 0..180; 180 disables sharp-edge alignment.
  double sharpAngleDeg = 35.0;
  /// Align the field to border edges.
  bool alignToBorders = true;
  /// Weight λ of the soft curvature alignment relative to smoothness (0 = smoothest field).
  /// Dimensionless; the built-in default is 200. Larger values follow the principal curvature
  /// directions more closely at the price of more singularities.
  double curvatureWeight = -1;  ///< negative: the built-in default
  /// The length, as a fraction of the bounding-box diagonal, over which the surface's curvature
  /// is spread before it places singularities (see field_generation.cpp, "Scale"): bumps smaller
  /// than this make no singularity pairs. 0 gives the field of the unmodified connection (one
  /// singularity pair per noisy bump); at most 1; negative: the built-in default, 0.02 (the edge
  /// of `fcql run`'s default quads).
  double scale = -1;
};

struct FieldGenerationReport {
  int sharpEdges = 0;        ///< number of sharp edges used as feature lines (constraints)
  int constrainedFaces = 0;  ///< faces with a hard alignment constraint
  /// Interior vertices whose own curvature is kept undiffused because the field would otherwise
  /// give them index +1/2 or more (sharp cones, spikes).
  int conesKept = 0;
  /// Quarter pairs of opposite singularities on the two ends of one edge, cancelled (a ±1/2
  /// pair counts 2; singularity_pairs.h).
  int pairsCancelled = 0;
  /// Pairs of an interior +1/4 and −1/4 closer than the field's scale, cancelled by the
  /// smoothest field around them (singularity_pairs.h).
  int closePairsCancelled = 0;
};

/// Per edge id (SurfaceMesh::edgeId): 1 if the dihedral angle exceeds `sharpAngleDeg`.
std::vector<char> detectSharpEdges(const SurfaceMesh& mesh, double sharpAngleDeg);

/// Throws FieldError if an option is out of range.
CrossField generateCrossField(const SurfaceMesh& mesh, const FieldGenerationOptions& options = {},
                              FieldGenerationReport* report = nullptr);

}  // namespace fcql
