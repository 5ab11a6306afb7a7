// Relaxation of a quad mesh towards the cross field, solved for all its vertices at once.
//
// Smoothing by local averages cannot turn a grid: rotating each quad about its own centre and
// averaging a vertex's corners in the quads around it gives the vertex back. Yet the grid near a
// singularity is turned: the layout's sides there leave the singularity within the tracing's
// angle tolerance φ of the field, and the quads along them follow the sides, not the field (on
// the kitten, 15% of the quads with an edge on a layout side were more than π/16 off the field,
// against 7% of the others, and 22% of the quads within three rings of a singularity).
//
// One sparse least-squares problem over the tangent moves x_v (two unknowns per free vertex, in
// a basis of the surface's tangent plane at the vertex) asks every edge a→b of every quad q to
// point along the cross direction c nearest to it, in the field's frame at the quad (the field
// and normal of the surface triangle nearest to its centre), at its present length l:
//   Σ_q Σ_{a→b} (h / l)² [ (Δ·c⊥)² + κ² (Δ·c − l)² ] + μ Σ_v |x_v|²,
//   Δ = p_b + T_b x_b − p_a − T_a x_a,
// h the mean edge length: each edge counts by its angle, not its length (short edges in thin
// quads turn as readily as long ones); κ = kFieldRelaxationLengthWeight keeps lengths more
// loosely than directions (a quad turns more readily than it stretches); μ keeps the moves
// small where the field cannot be followed everywhere at once (near singularities, over a field
// that curls). Eigen's conjugate gradients solve the normal equations, assembled directly, to a
// relative residual of 1e-3 or for at most 100 iterations (the anchor keeps them conditioned
// alike at any mesh size; as good as 200 on the shared meshes; a direct factorisation cost 4 s
// a round on 150K quads, more than the rest of the stage); each moved vertex then goes back to
// the surface at its closest point. The caller keeps quads from folding (the moves are
// proposals).
#pragma once

#include "mesh/closest_point_index.h"
#include "mesh/quad_mesh.h"

#include <vector>

namespace fcql {

/// κ above.
constexpr double kFieldRelaxationLengthWeight = 0.3;
/// The conjugate gradients' relative residual and iteration limit.
constexpr double kFieldRelaxationTolerance = 1e-3;
constexpr int kFieldRelaxationIterations = 100;

struct FieldRelaxation {
  std::vector<Vec3> positions;  ///< per vertex: where it would go (on the surface); fixed ones where they were
  bool solved = false;          ///< false: nothing to solve or no finite solution (positions as they were)
};

/// `triangleNormals` and `triangleDirections` are per triangle of `surface` (a zero direction:
/// no field there; quads nearest to it ask nothing). `movable`: per vertex, whether it may move.
/// `anchor` is μ above (the edges' rows weigh h / l each).
FieldRelaxation relaxTowardsField(const QuadMesh& quads, const ClosestPointIndex& surface,
                                  const std::vector<Vec3>& triangleNormals, const std::vector<Vec3>& triangleDirections,
                                  const std::vector<char>& movable, double anchor);

}  // namespace fcql
