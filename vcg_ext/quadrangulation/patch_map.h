// PatchMap: a layout patch (a disk cut out of the layout's refined triangle mesh) mapped onto
// a rectangle with mean-value coordinates (Floater), given where its boundary goes. Copies of
// a vertex that the boundary meets twice (a cut through a cylinder) are kept apart. With a
// PatchGuide, the mean-value map is then replaced by a field-aligned one (field_aligned_map.h)
// unless that folds: it is then blended back towards the mean-value map until it does not.
#pragma once

#include "layout/patch_layout.h"
#include "quadrangulation/field_aligned_map.h"

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace fcql {

/// What the field-aligned map of a patch needs: the cross field (direction 0 per face of the
/// input, indexed by PatchLayout::originalFace), and per position of the patch's boundary loop
/// whether it is fixed or slides along its side (FieldAlignedProblem::Constraint; empty: all fixed).
struct PatchGuide {
  const std::vector<Vec3>* faceDirections = nullptr;
  std::vector<std::int8_t> loopConstraint;
};

/// How a guided map came out.
enum class GuidedMap { None, Aligned, Blended, MeanValue };

class PatchMap {
public:
  /// `boundaryUv(k)` gives the image of the boundary loop position k of the patch.
  /// `halfEdges` maps (a,b) of the layout triangles to t*3+i. Throws std::runtime_error if the
  /// linear system cannot be solved.
  PatchMap(const PatchLayout& layout, int patch, const std::vector<int>& triangles,
           const std::unordered_map<std::uint64_t, int>& halfEdges, const std::function<Vec2(int)>& boundaryUv,
           const PatchGuide* guide = nullptr);

  /// The field-aligned problem the guided constructor would solve for this patch, unsolved,
  /// and per boundary loop position its wedge's number in it (`loopWedges`): for solving
  /// several patches together (patch_sampling.cpp).
  static FieldAlignedProblem alignedProblem(const PatchLayout& layout, int patch, const std::vector<int>& triangles,
                                            const std::unordered_map<std::uint64_t, int>& halfEdges,
                                            const std::function<Vec2(int)>& boundaryUv, const PatchGuide& guide,
                                            std::vector<int>& loopWedges);

  /// The image of boundary loop position k (moved along its side if it slides).
  Vec2 loopImage(int k) const;
  GuidedMap guided() const { return guided_; }

  /// The surface point whose image is `uv`. A `uv` outside every mapped triangle (a map that
  /// rounding or a degenerate patch left not quite covering its rectangle) is put on the
  /// nearest one and counted in outsidePoints(); throws std::runtime_error if the patch has no
  /// usable triangle.
  Vec3 pointAt(const Vec2& uv) const;
  /// How many pointAt() queries fell farther than rounding outside the map.
  int outsidePoints() const { return outside_; }

  static std::uint64_t edgeKey(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }

private:
  /// `map` false: only the wedges and the boundary's images (for alignedProblem).
  PatchMap(const PatchLayout& layout, int patch, const std::vector<int>& triangles,
           const std::unordered_map<std::uint64_t, int>& halfEdges, const std::function<Vec2(int)>& boundaryUv,
           const PatchGuide* guide, bool map);
  /// The field-aligned problem of the patch; `index` maps wedges to their numbers in it,
  /// `wedgeOf` back.
  FieldAlignedProblem problem(const PatchGuide& guide, const std::unordered_map<std::uint64_t, int>& halfEdges,
                              std::unordered_map<int, int>& index, std::vector<int>& wedgeOf) const;
  int wedge(int t, int c) const;
  /// The images of the interior wedges (mean-value coordinates), the boundary's being set.
  void mapInterior();
  /// The field-aligned map replacing the mean-value one (see PatchGuide).
  void alignToField(const PatchGuide& guide, const std::unordered_map<std::uint64_t, int>& halfEdges);
  /// Per triangle its corners' images, and the grid over them that pointAt() searches.
  void indexTriangles();
  int cellCoordinate(double value, int axis) const;

  const PatchLayout& layout_;
  int patch_;
  std::vector<int> triangles_;
  std::unordered_map<int, int> slotOf_;
  mutable std::vector<int> parent_;
  mutable int outside_ = 0;
  std::unordered_map<int, Vec2> uv_;
  std::vector<int> loopWedge_;
  GuidedMap guided_ = GuidedMap::None;
  // Per triangle (in triangles_' order) its corners' images, and a grid of gridN_ × gridN_
  // cells over them listing the triangles whose box meets each cell.
  std::vector<std::array<Vec2, 3>> corners_;
  Vec2 gridLow_ = Vec2::Zero(), gridHigh_ = Vec2::Zero(), gridStep_ = Vec2::Ones();
  int gridN_ = 0;
  std::vector<int> cellBegin_, cellTriangles_;
};

}  // namespace fcql
