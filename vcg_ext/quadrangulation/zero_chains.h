// Zero chains (§4.4): patches whose opposite sides cannot get equal integer lengths because
// of t-junctions are split by one Catmull–Clark step. A patch whose sides hold n segments in
// all (4 plus one per t-junction on its boundary) is an n-gon: it is mapped onto a regular
// n-gon (each segment onto one edge, by arc length), every segment is halved, and the n-gon
// becomes n quads around a centre node of valence n. The t-junctions of the patch become
// corners of its parts (valence 3), so the strips that ran into them now end at the centre:
// the chain of equalities that forced a zero is broken. The halved segments put new
// t-junctions on the neighbours, which get hard opposite-side equalities. A part that is split
// again is cut the same way inside its chart.
#pragma once

#include "quadrangulation/patch_sides.h"

#include <vector>

namespace fcql {

/// Splits the listed (active) patches of `graph` as above.
void splitPatches(PatchGraph& graph, const PatchLayout& layout, const std::vector<int>& patches);

/// Splits every n-gon layout patch (PatchSides::polygonCorners > 0: a disk whose corners are
/// not 4, which the layout reports as invalid) the same way, into quads; returns how many.
int splitPolygonPatches(PatchGraph& graph, const PatchLayout& layout);

}  // namespace fcql
