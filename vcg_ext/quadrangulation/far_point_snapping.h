// Quad vertices moved onto the points of the surface the quads miss.
//
// On a scan, the quads' distance to the surface is mostly that of a few spots: a claw's tip, a
// spike or the edge of a fin narrower than a quad, which the quads cut across. Smaller quads
// everywhere (the quad stage's refinements) reach them only once they are about as small as the
// spot (the dragon with fcql's own field: 20K quads 2.96 times the bound away, then 44K, 107K and
// 192K quads, the last within it by 0.03%, all for a few such spots). Here the vertex of the
// quads nearest to such a point goes onto it instead, one vertex per spot, so that the quads
// reach it. Where that vertex alone would spoil its quads (a spike longer than they are wide),
// pullVerticesToFarPoints takes it there all the same and smooths the quads around it to follow.
#pragma once

#include "mesh/closest_point_index.h"
#include "mesh/quad_mesh.h"
#include "quadrangulation/quad_smoothing.h"

#include <array>
#include <vector>

namespace fcql {

/// `far`: points where the quads and the surface may be farther apart than `limit` (as
/// measureDeviation finds them, on either surface). Those on the surface (`surface`, within a
/// millionth of `limit`) that are farther than `limit` from the quads are taken farthest first;
/// each takes the nearest corner of the quad triangle nearest to it, unless a point taken before
/// lies closer to it than its own distance to the quads (the same spot: the next measurement
/// tells whether it is still missed). A vertex on the border of the quads is not moved, nor one
/// whose move would take a quad that depends on it (QuadJacobian) to a scaled Jacobian of `floor`
/// or below where it was above (or fold one), or put the midpoint of one of its quad edges
/// farther than `limit` from the surface (a bridge to another part of it, across a gap narrower
/// than a quad); the triangle's next corner is tried.
/// Where the spots (the points left once those near one before are dropped) are more than 16 and
/// more than 1% of the quads' vertices, the quads miss the surface widely, not at a few tips
/// (quads far coarser than its curves, or a bound finer than its detail): nothing moves.
/// With `pulled`, the spot goes to the nearest corner that does not bridge (nor is on the border)
/// even where that corner's quads would spoil: it is then listed in `pulled` (once: it is not
/// moved again), and the caller moves the quads around it (e.g. smooths them with it held) and
/// checks them.
/// Returns how many vertices moved. The connectivity does not change, and moved vertices lie on
/// the surface.
int snapVerticesToFarPoints(QuadMesh& quads, const ClosestPointIndex& surface, const std::vector<Vec3>& far,
                            double limit, double floor, std::vector<int>* pulled = nullptr);

/// snapVerticesToFarPoints with `pulled`, then the quads within `rings` rings of the pulled
/// vertices smoothed (`smoothing`, its `frozen` replaced: the pulled vertices held where they
/// went, all but those rings frozen), so that they follow a spike longer than they are wide up to
/// its tip. Each part of those rings apart from the others is undone, its pulled vertices
/// included, if it folds a quad (QuadJacobian at 0 or below) that was not folded. Returns how
/// many vertices are left on the far points they went onto.
int pullVerticesToFarPoints(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                            const std::vector<std::array<int, 3>>& surfaceTriangles, const ClosestPointIndex& surface,
                            const std::vector<Vec3>& far, double limit, double floor, SmoothingOptions smoothing,
                            int rings);

}  // namespace fcql
