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
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fcql {

struct LayoutSegment {
  std::vector<int> vertices;  ///< layout vertex ids, node to node, as first met (patchA on the left);
                              ///< empty for segments made by zero-chain splits
  std::vector<Vec3> polyline; ///< the segment's points, node to node
  int nodeA = -1, nodeB = -1; ///< node ids of its ends (see PatchGraph)
  double length = 0;          ///< length of the polyline
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
  std::array<int, 4> corners{};                   ///< node ids of the corners
  int layoutPatch = -1;       ///< the layout patch this (part of a) patch lies in
  /// A part made by a zero-chain split lies in a polygon chart of its layout patch
  /// (PatchGraph::charts); chartCorners are its corners there, counter-clockwise. −1: the
  /// patch is a whole layout patch.
  int chart = -1;
  std::array<Vec2, 4> chartCorners{};
  bool active = true;         ///< false once split
  bool original = true;       ///< sides are the layout patch's own boundary, segment for segment
  bool forceEqual = false;    ///< opposite sides equal as a hard constraint even with t-junctions
  /// > 0 for a layout patch that is a disk with this many corners (3, 5, 6, ...): all its
  /// segments are in sides[0], in order, and splitPolygonPatches() cuts it into quads.
  int polygonCorners = 0;
};

/// A layout patch mapped onto a convex polygon (a regular n-gon, one edge per segment of its
/// boundary when it was split): the image of each position of its boundary loop.
struct PolygonChart {
  int layoutPatch = -1;
  std::vector<Vec2> loopUv;
  std::map<int, Vec2> nodeUv;  ///< the n-gon's vertices: node id → position
};

/// Node ids: layout vertex ids, then numLayoutVertices + i for extraNodes[i] (side midpoints
/// and centres made by zero-chain splits).
struct PatchGraph {
  std::vector<LayoutSegment> segments;
  std::vector<PatchSides> patches;  ///< the layout patches first (same index), then split parts
  int numLayoutVertices = 0;
  std::vector<Vec3> extraNodes;
  std::vector<PolygonChart> charts;

  Vec3 nodePosition(const PatchLayout& layout, int node) const {
    return node < numLayoutVertices ? layout.positions[node] : extraNodes[node - numLayoutVertices];
  }
};

/// Throws std::runtime_error naming the first patch that is not a disk with at least 3 corners.
PatchGraph buildPatchGraph(const PatchLayout& layout);

}  // namespace fcql
