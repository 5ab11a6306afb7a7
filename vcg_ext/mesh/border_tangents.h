// The direction of the border at the scale of a quad, for borders that zigzag.
//
// A computed cross field is tangent to the border (field_generation.h), and the field analysis
// counts a border vertex's index from the field's turn against the border there
// (field_analysis.h). Where the border is smooth at the scale of its triangles, each border
// edge's own direction is the border's. The borders of scans are often not: a hole where the
// scanner saw nothing, or faces cut away, leaves a border that zigzags from triangle to
// triangle, turning by 30–60° at every vertex. A field constrained edge by edge turns with it,
// and nearly every turn became a border singularity: a bunny with 12 holes cut into it had 163
// border singularities and 1544 layout patches for 7.2K quads, 8 of them invalid.
//
// So along each border loop, an edge shorter than half a quad (`reach` / 2) and more than
// kJaggedDeg off the border's mean direction around it is given that mean direction as the
// border's. The mean is length-weighted over a window of `reach` on each side of the edge's
// midpoint along the loop, shortened on both sides alike so that it does not run past a corner
// of the border: a vertex where the chords to the vertices rc back and rc ahead along the loop
// turn by more than kBorderCornerDeg, and by no less than at any vertex within rc (rc: `reach`,
// but at least three of the loop's mean edges, so that one triangle's zigzag is not a corner,
// and at most a sixth of the loop). A corner of a CAD sheet or of a cut stays a corner. On a
// loop shorter than 12 reaches (a small hole) the window shrinks to a twelfth of its length.
// Edges as long as half a quad are the border's shape, which the quads follow: the camelhead's
// border has notches of such edges, whose tips stay patch corners. Smooth borders (the shared
// lilium, camelhead and aqua_center) keep every edge's own direction.
//
// The field analysis rounds a border vertex's index with the field's misalignment to its two
// border edges measured against these directions where the field follows them, and keeps each
// quarter on a vertex of its kind (field_analysis.h).
#pragma once

#include "mesh/surface_mesh.h"

#include <unordered_map>

namespace fcql {

/// The reach SurfaceMesh uses, as a fraction of the bounding-box diagonal: the edge of a
/// default quad (`fcql run`'s --scale) and the default field scale.
constexpr double kBorderTangentReach = 0.02;

/// Per edge id (SurfaceMesh::edgeId) of each border edge whose direction differs from the
/// border's (see above): the border's unit direction there, pointing the way the edge runs in
/// its face. Border edges not listed follow their own direction. `reach` is a length (0: none
/// is listed).
std::unordered_map<int, Vec3> zigzagBorderTangents(const SurfaceMesh& mesh, double reach);

}  // namespace fcql
