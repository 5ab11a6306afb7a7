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
#include "quadrangulation/patch_map.h"
#include "quadrangulation/side_lengths.h"

#include <unordered_map>
#include <vector>

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

/// The grids of whole layout patches that samplePatches mapped before, for its later calls on
/// the same layout (the quad stage's passes at one size sample most patches alike: the fold
/// rounds and the distance fallbacks change a few). A patch mapped the same way, onto a
/// rectangle of the same size, with its boundary exactly where it was (to the last bit: the
/// quads downstream are that sensitive), takes its grid from here instead of being mapped
/// again: the same grid, faster.
struct SampledGrids {
  /// How many grids are kept per layout patch (the oldest go first).
  static constexpr std::size_t kPerPatch = 4;
  struct Grid {
    int W = 0, H = 0;
    bool guided = false;           ///< mapped field-aligned (else with mean-value coordinates)
    std::vector<Vec2> boundaryUv;  ///< where its boundary loop went
    std::vector<Vec3> inner;       ///< its inner grid points, row by row
    GuidedMap kind = GuidedMap::None;
    int outsidePoints = 0;
  };
  std::unordered_map<int, std::vector<Grid>> byPatch;
};

/// `grids`, if given, is read and extended (SampledGrids).
QuadMesh samplePatches(const PatchLayout& layout, const PatchGraph& graph, const SideLengths& lengths,
                       const std::vector<Vec3>* faceDirections = nullptr,
                       const std::vector<char>* meanValuePatches = nullptr, SampledGrids* grids = nullptr);

}  // namespace fcql
