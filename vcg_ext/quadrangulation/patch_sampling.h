// Sampling each quad patch with its integer grid (§4.5).
//
// Each patch (a disk with 4 corners, cut out of the layout's refined triangle mesh) is mapped
// to the rectangle [0, W] × [0, H] of its integer side lengths: the boundary by arc length
// along each segment (so that a segment shared by two patches maps to the same points from
// both sides), the interior by mean-value coordinates (Floater), which keep the map one-to-one
// inside a convex domain. Grid points inside are located in the mapped triangles and placed
// on the surface; points on the sides are taken once per segment and shared, so the quads of
// neighbouring patches meet conformingly.
#pragma once

#include "mesh/quad_mesh.h"
#include "quadrangulation/side_lengths.h"

namespace fcql {

/// Throws std::runtime_error if a patch's opposite sides differ (a zero chain left) or its
/// mapping fails.
/// The boundary loop of layout patch p mapped onto the unit square: side k (from corner k)
/// onto the k-th side of the square, by arc length.
std::vector<Vec2> unitSquareBoundary(const PatchLayout& layout, int p);

/// With `faceDirections` (the cross field's direction 0 per input face, indexed by
/// PatchLayout::originalFace), each whole layout patch is mapped field-aligned instead
/// (field_aligned_map.h): first all of them together, the points inside their sides free to
/// slide along them and each shared by the two patches of its side (one unknown per point,
/// which both patches' maps read), which gives each segment's parameter (arc length where a
/// split part lies on it), then each again with its sides fixed there. A map that folds is
/// blended back towards mean-value coordinates (QuadMesh counts them). Layout patches marked
/// in `meanValuePatches` (per layout patch) get arc length on their sides: kArcLengthSides
/// keeps the field-aligned map inside, kMeanValuePatch mean-value coordinates.
constexpr char kFieldPatch = 0, kMeanValuePatch = 1, kArcLengthSides = 2;
QuadMesh samplePatches(const PatchLayout& layout, const PatchGraph& graph, const SideLengths& lengths,
                       const std::vector<Vec3>* faceDirections = nullptr,
                       const std::vector<char>* meanValuePatches = nullptr);

}  // namespace fcql
