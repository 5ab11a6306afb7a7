// Step 1b of the layout (issue 20): more ports covered by the first program's selection.
// The first 0-1 program (Eq. 4) trades covering ports against length, and may leave a port
// dangling where a selection of H that covers every port exists; propagation then ends that
// port at a t-junction. Solving the whole program with covering first instead is much slower
// on large fields (the dragon's relaxation 25 s instead of 1 s: its weights are all nearly
// equal). Here the dangling ports get neighbourhoods of H instead, all of them together first,
// then each alone: the arcs at the ports, the selected arcs they conflict with (same port or
// tangential crossing), the arcs at those arcs' ports, and so on for a few steps. A
// neighbourhood's selected arcs are freed and its arcs that conflict with no selected arc
// outside it are selected again, covering ports first and then the shortest in all
// (SelectionScope::coverageFirst); the result is kept where it covers more ports than what it
// replaces.
#pragma once

#include "tracing/separatrix_graph.h"

#include <vector>

namespace fcql {

struct CoverageRepairReport {
  int programs = 0;      ///< neighbourhood programs solved
  int accepted = 0;      ///< ... kept (each covered more ports)
  int portsGained = 0;   ///< ports covered after the repair minus before
  int stalledParts = 0;  ///< parts of those programs stopped at the stall limit
  int timeLimitedParts = 0;
  double seconds = 0;
};

/// `selected`: arcs of `h` chosen so far (a valid packing: no port twice, no tangential pair);
/// on return, the repaired selection, increasing. Every arc of H joins two different ports (a
/// search never ends at its own port), so one arc more covers two ports more. All the
/// neighbourhood programs together get `timeLimitSeconds` (a safety stop: one that finds no
/// time left counts in timeLimitedParts), each `stallNodes` as selectSeparatrices does.
CoverageRepairReport repairCoverage(const SeparatrixGraph& h, std::vector<int>& selected, double timeLimitSeconds,
                                    long stallNodes);

}  // namespace fcql
