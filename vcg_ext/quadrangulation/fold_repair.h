// Repair of the quads the greedy untangling of quad_smoothing leaves folded.
//
// That untangling moves one vertex at a time and never lets a quad get worse, so a fold that
// needs several vertices to move together, some quads getting worse on the way, stays. Here
// the movable vertices within a few rings of the folded quads (1, 2, 4 and 8 rings, while folds
// are left) move together: they minimise
//   E = Σ over the corners of the quads around them of max(0, ε − J)² + max(0, ε − α / A)²,
// J the corner's scaled Jacobian (e1 × e2)·n / (|e1| |e2|) and α its area (e1 × e2)·n against a
// fixed normal n at the corner (the input surface's, averaged over the quads around the vertex),
// A the square of the quad's mean edge length at the start, ε = 0.2. E has no barrier: it is
// finite, and smooth, for inverted corners too, so a folded quad can be pulled through flat;
// the area term keeps corners from collapsing to a point, where J has no gradient. Then the same
// descent again with the quad mesh's own normals instead (the normal at each corner from the
// quads around it, and each quad's own): what the caller counts as folded. Each vertex moves in
// its tangent plane (the gradient by central differences, scaled by the square of its mean edge
// length, as J does not depend on the scale) with a backtracking line search, and goes back onto
// the surface (its closest point), or a vertex on a feature line onto that line, after each step.
// Each connected part of the region is tried on its own and kept only when, by `jacobian` (the
// figure the caller counts), fewer of the quads around it are folded and none that was not
// folded falls to 0.02 or below its figure, whichever is lower. The connectivity does not change.
#pragma once

#include "mesh/closest_point_index.h"
#include "mesh/quad_mesh.h"
#include "metrics/quad_quality.h"

#include <vector>

namespace fcql {

/// How a vertex may move: not at all, on the surface (to its closest point), or along the
/// feature lines (to their closest point: a vertex on a crease stays on it).
enum RepairMove : char { kStays = 0, kOnSurface = 1, kAlongFeature = 2 };

/// `triangleNormals`: the unit normal of each triangle of `surface`; `features`: the feature
/// lines as degenerate triangles (may be null when no vertex moves kAlongFeature);
/// `moves[v]`: a RepairMove per vertex. With a `margin` > 0, quads at or below it (folded, or
/// nearly flat at a corner) are repaired too: a part is then kept when it leaves fewer folded
/// quads, or as many and fewer at or below the margin. Returns how many quads were unfolded
/// (how many fewer are at or below the margin, with one).
int repairFolds(QuadMesh& quads, const ClosestPointIndex& surface, const ClosestPointIndex* features,
                const std::vector<Vec3>& triangleNormals, const std::vector<char>& moves, const QuadJacobian& jacobian,
                double margin = 0);

}  // namespace fcql
