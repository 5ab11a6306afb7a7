// Cancelling pairs of opposite singularities (+1/4 and −1/4, +1/2 and −1/2, ...) that sit on
// the two ends of one mesh edge.
//
// Such a pair is finer than anything a quad layout can serve: its separatrices cut patches a
// fraction of a triangle wide (on a noisy scan, a sliver triangle whose angles the noise
// turned over makes one). The field is changed in one of the two triangles on the pair's
// edge, a quarter off each end at a time: one cross turns by the smallest multiple of 5
// degrees (up to 45 either way) that takes a quarter off the index of both ends and leaves the
// triangles' other vertices as they were, or else both crosses together. What no such turn
// cancels is left as it is. Faces marked fixed (crosses constrained to sharp or border edges)
// are never changed.
#pragma once

#include "field/cross_field.h"

#include <vector>

namespace fcql {

/// Returns the number of quarter pairs cancelled (a ±1/2 pair counts 2). `fixedFace` (empty:
/// none) marks the faces to keep.
int cancelAdjacentSingularityPairs(const SurfaceMesh& mesh, CrossField& field, const std::vector<char>& fixedFace = {});

}  // namespace fcql
