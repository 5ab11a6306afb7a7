// Regions without singularities to anchor a layout (paper §4.2 end): cylinders, tori, or any
// patch that is not a topological disk after the layout is solved. A field line is traced
// through a regular vertex in the middle of such a patch, used as a "virtual" singularity with
// its four (regular) ports: if two opposite ports reach the patch boundary (another
// separatrix, orthogonally, or the border), the line between them cuts the region (a cylinder
// becomes a quad); otherwise the shortest field line that closes on itself is added (a torus
// gets its two loops). Repeated until every patch is a disk or no line can be added.
#pragma once

#include "layout/patch_layout.h"

#include <memory>

namespace fcql {

struct ClosingReport {
  int virtualVertices = 0;  ///< regular vertices used as anchors
  int linesAdded = 0;
  double seconds = 0;
};

/// `analysis` gains the virtual singularities (index 0) and `graph` is rebuilt on it when
/// needed; `layout` gains the field lines; `patches` is recomputed.
ClosingReport closeNonDiskPatches(const SurfaceMesh& mesh, const CrossField& field, FieldAnalysis& analysis,
                                  std::unique_ptr<GeodesicGraph>& graph, Layout& layout, PatchLayout& patches,
                                  int maxLines = 16);

/// The same path walked backwards.
TracedPath reversedPath(const TracedPath& path);

}  // namespace fcql
