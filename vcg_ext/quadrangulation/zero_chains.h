// Zero chains (§4.4): patches whose opposite sides cannot get equal integer lengths because
// of t-junctions are split in four, one Catmull–Clark step: a node at the middle of each side
// (by arc length; the segment there is split, which may put a new t-junction on the
// neighbour), a centre node, and four inner segments from the side middles to the centre,
// traced as straight lines in the patch's map onto the unit square. The parts and the
// neighbours that gained a t-junction get hard opposite-side equalities.
#pragma once

#include "quadrangulation/patch_sides.h"

#include <vector>

namespace fcql {

/// Splits the listed (active) patches of `graph` in four.
void splitPatches(PatchGraph& graph, const PatchLayout& layout, const std::vector<int>& patches);

}  // namespace fcql
