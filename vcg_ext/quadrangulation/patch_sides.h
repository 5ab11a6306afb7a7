// The sides of the patches of a layout, as chains of layout edges between nodes (§4.4).
//
// A node is a vertex that is a corner of at least one patch (singularities, separatrix
// crossings, t-junctions, border corners). A segment is the chain of layout edges between two
// consecutive nodes; it is shared by the two patches on its sides (one on the border). Each
// side of a quad patch (between two of its corners) is a sequence of segments: one if no
// t-junction lies on it, more otherwise.
#pragma once

#include "layout/patch_layout.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fcql {

struct LayoutSegment {
  std::vector<int> vertices;  ///< layout vertex ids, node to node, as first met (patchA on the left)
  double length = 0;          ///< Euclidean length of the chain
  int patchA = -1, patchB = -1;
};

/// A segment used by a side: its id, and whether the side runs it backwards.
struct SideSegment {
  int segment;
  bool reversed;
  int loopStart;  ///< position in the patch's boundary loop where the side enters the segment
};

struct PatchSides {
  std::array<std::vector<SideSegment>, 4> sides;  ///< counter-clockwise, side k from corner k to k+1
  std::array<int, 4> corners{};                   ///< layout vertex ids of the corners
};

struct PatchGraph {
  std::vector<LayoutSegment> segments;
  std::vector<PatchSides> patches;  ///< one per layout patch
};

/// Throws std::runtime_error naming the first patch that is not a disk with 4 corners.
PatchGraph buildPatchGraph(const PatchLayout& layout);

}  // namespace fcql
