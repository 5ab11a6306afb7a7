// Cutting the surface along the layout's separatrices and extracting its patches (§4).
//
// Every triangle crossed by separatrices is split along them (an arrangement of straight
// chords per triangle, including their mutual crossings and t-junction ends, triangulated
// without zero-area triangles), so that each separatrix becomes a chain of edges of a refined
// triangle mesh. Patches are the connected components of triangles across the remaining
// edges. Corners are found combinatorially along each patch boundary: a corner is where the
// boundary passes from one separatrix (or the border) to another, or to another stretch of the
// same separatrix (a separatrix crossing itself), at a singular vertex, or at
// a border vertex whose border index is not zero. A t-junction is therefore a corner only for
// the patches on the side of the separatrix that ends there.
#pragma once

#include "layout/layout_solver.h"

#include <string>
#include <vector>

namespace fcql {

struct PatchReport {
  int triangles = 0;
  int boundaryLoops = 0;
  int eulerCharacteristic = 0;
  int corners = 0;
  bool isDisk = false;
  bool valid = false;  ///< a disk with 4 corners
  std::string problem; ///< why not valid
  /// The first boundary loop, patch on the left: vertex ids in order, and per position 1 if
  /// that vertex is a corner of this patch.
  std::vector<int> loop;
  std::vector<char> loopCorner;
  /// Per position: the triangle whose edge leaves loop[k] along the boundary (tells apart the
  /// copies of a vertex that the loop meets twice, e.g. on a cut through a cylinder).
  std::vector<int> loopTriangle;
};

struct PatchLayout {
  std::vector<Vec3> positions;               ///< original vertices first, then new ones
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> originalFace;             ///< per triangle
  std::vector<int> patch;                    ///< per triangle
  /// Per triangle and local edge (i → i+1): separatrix index in Layout::separatrices, −2 on
  /// the border, −1 inside a patch.
  std::vector<std::array<int, 3>> edgeCurve;
  /// Per triangle and local edge on a separatrix: the path parameter (segment index +
  /// fraction) at its two ends, corner i and corner i+1. Tells a separatrix crossing itself
  /// from one running straight on.
  std::vector<std::array<std::array<double, 2>, 3>> edgeParam;
  std::vector<char> corner;                  ///< per vertex: 1 at a patch corner
  std::vector<PatchReport> patches;
  int numOriginalVertices = 0;
  /// Corners added on the boundaries of disk patches that had fewer than 3 (see
  /// addBoundaryCorners in patch_layout.cpp): those patches are then cut as 3-gons.
  int addedCorners = 0;

  int numPatches() const { return int(patches.size()); }
  int numInvalidPatches() const;
  /// Histogram of corner counts over the disk patches: {corners, patches}.
  std::vector<std::pair<int, int>> cornerHistogram() const;
};

/// Throws std::runtime_error if the separatrices cannot be embedded (a bug, reported).
/// Disk patches with fewer than 3 corners get corners added (addBoundaryCorners).
PatchLayout buildPatchLayout(const GeodesicGraph& graph, const Layout& layout);

/// A disk patch with fewer than 3 corners (a teardrop closed by one separatrix around a
/// singularity of index 3/4, a lens between two, or a cap inside a closed loop) has no polygon
/// to be cut into quads. Boundary vertices of `patch` (on its first loop, met once by it) are
/// made corners until it has 3: each splits the longest stretch of the boundary between
/// corners at its middle (by length); the neighbour on that side sees the new corner as a
/// t-junction. Updates the report, `corner` and addedCorners; returns how many were added.
int addBoundaryCorners(PatchLayout& layout, int patch);

}  // namespace fcql
