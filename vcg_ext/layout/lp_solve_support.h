// Pieces of the lp_solve front ends shared by IntegerProgram and the set-packing solver: the
// owning model pointer and the stall limit (branch and bound stops once its best solution
// has not improved for a while). Internal: included by .cpp files only.
#pragma once

#include <lpsolve/lp_lib.h>

#include <chrono>
#include <memory>

namespace fcql {

using LpModel = std::unique_ptr<lprec, void (*)(lprec*)>;

/// What branch and bound has found so far, for the stall limit: lp_solve reports each
/// improved solution (a message callback) and asks often whether to stop (an abort callback).
struct StallWatch {
  double limitSeconds = 0;
  bool haveSolution = false;  ///< set before solving when a solution is known already
  bool stopped = false;
  std::chrono::steady_clock::time_point lastImprovement;
};

/// Installs the two callbacks on `lp` if `watch.limitSeconds` > 0; `watch` must outlive the
/// solve.
void watchForStall(lprec* lp, StallWatch& watch);

/// Sets lp_solve's time limit (whole seconds, at least 1; infinite or huge limits are capped
/// at a million seconds rather than overflowing the conversion).
void setTimeLimit(lprec* lp, double seconds);

/// lp_solve may "solve" an unbounded model to its infinity (1e30).
bool objectiveAtInfinity(lprec* lp);

}  // namespace fcql
