// Pieces of the lp_solve front ends shared by IntegerProgram and the set-packing solver: the
// owning model pointer, the work limits of branch and bound (in nodes: the result never
// depends on the machine's speed) and the time limit (a safety stop only). Internal: included
// by .cpp files only.
#pragma once

#include <lpsolve/lp_lib.h>

#include <memory>

namespace fcql {

using LpModel = std::unique_ptr<lprec, void (*)(lprec*)>;

/// Work limits of one branch and bound, counted in lp_solve's branch-and-bound nodes rather
/// than seconds, so that the same program stops at the same node, with the same solution, on
/// any machine however busy: lp_solve reports each improved solution (a message callback) and
/// asks often whether to stop (an abort callback); both read its node count.
struct BranchAndBoundWatch {
  long stallNodes = 0;        ///< stop once a solution is known and this many nodes brought no better one (0: never)
  long nodeLimit = 0;         ///< stop after this many nodes in all (0: no limit)
  bool haveSolution = false;  ///< set before solving when a solution is known already
  long lastImprovementNode = 0;
  bool stalled = false;           ///< stopped by stallNodes
  bool nodeLimitReached = false;  ///< stopped by nodeLimit
  bool stopped() const { return stalled || nodeLimitReached; }
};

/// Installs the two callbacks on `lp` if either limit is set; `watch` must outlive the solve.
void watchBranchAndBound(lprec* lp, BranchAndBoundWatch& watch);

/// Sets lp_solve's time limit (whole seconds, at least 1; infinite or huge limits are capped
/// at a million seconds rather than overflowing the conversion). A safety stop: the results
/// depend on the machine's speed when it is reached, and every caller reports it.
void setTimeLimit(lprec* lp, double seconds);

/// lp_solve may "solve" an unbounded model to its infinity (1e30).
bool objectiveAtInfinity(lprec* lp);

}  // namespace fcql
