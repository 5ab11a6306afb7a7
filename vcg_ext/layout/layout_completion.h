// Step 2b of the layout (issue 20): completing a layout the solving cycle left with dangling
// ports. After the cycle, a dangling port is one from which every path to another dangling
// port meets the frozen layout tangentially; propagation would end it at a t-junction. Here
// the separatrices in the way are freed: for each path between two dangling ports (searched
// without barriers), the separatrices it meets tangentially. Their ports and the dangling ones
// are then matched again by the solving cycle, with weights that put covering ports before
// length (the paper's Completeness, made worth more than any length saving, instead of Eq. 4
// alone). A trial is kept only where propagation would then leave fewer t-junctions and
// unresolved ports; the sets are tried fewest and shortest first, within a number of trials.
#pragma once

#include "layout/layout_solver.h"

#include <vector>

namespace fcql {

/// Changes `layout` only by trials that leave fewer t-junctions; the layout must not have been
/// propagated yet (only Full separatrices).
CompletionReport completeLayout(const GeodesicGraph& graph, Layout& layout, const LayoutParameters& params);

/// The ids of the barriers `path` meets tangentially (barrierContact: in a shared triangle,
/// along the same direction up to a half turn), increasing and distinct.
std::vector<int> tangentialBlockers(const TracedPath& path, const BarrierSet& barriers);

/// T-junctions plus unresolved ports that propagation (step 3) would leave on `layout`.
int propagationDefects(const GeodesicGraph& graph, const Layout& layout);

}  // namespace fcql
