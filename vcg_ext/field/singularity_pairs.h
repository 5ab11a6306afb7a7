// Cancelling ±1/4 singularity pairs that sit on the two ends of one mesh edge.
//
// Such a pair is finer than anything a quad layout can serve: its separatrices cut patches a
// fraction of a triangle wide (on a noisy scan, a sliver triangle whose angles the noise
// turned over makes one). The field is changed in one of the two triangles on the pair's
// edge: its cross turns by the smallest multiple of 5 degrees (up to 85) that leaves the two
// vertices and the triangles' other vertices all regular. A pair no such turn cancels is left
// as it is. Faces marked fixed (crosses constrained to sharp or
// border edges) are never changed.
#pragma once

#include "field/cross_field.h"

#include <vector>

namespace fcql {

/// Returns the number of pairs cancelled. `fixedFace` (empty: none) marks the faces to keep.
int cancelAdjacentSingularityPairs(const SurfaceMesh& mesh, CrossField& field, const std::vector<char>& fixedFace = {});

}  // namespace fcql
