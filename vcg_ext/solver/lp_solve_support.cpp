#include "solver/lp_solve_support.h"

#include <algorithm>
#include <cmath>

namespace fcql {
namespace {

void __WINAPI noteImprovement(lprec* lp, void* handle, int) {
  auto* watch = static_cast<BranchAndBoundWatch*>(handle);
  watch->haveSolution = true;
  watch->lastImprovementNode = long(get_total_nodes(lp));
}

int __WINAPI workLimitReached(lprec* lp, void* handle) {
  auto* watch = static_cast<BranchAndBoundWatch*>(handle);
  const long nodes = long(get_total_nodes(lp));
  if (watch->nodeLimit > 0 && nodes >= watch->nodeLimit) {
    watch->nodeLimitReached = true;
    return TRUE;
  }
  if (watch->stallNodes > 0 && watch->haveSolution && nodes - watch->lastImprovementNode >= watch->stallNodes) {
    watch->stalled = true;
    return TRUE;
  }
  return FALSE;
}

}  // namespace

void watchBranchAndBound(lprec* lp, BranchAndBoundWatch& watch) {
  if (watch.stallNodes <= 0 && watch.nodeLimit <= 0) return;
  put_msgfunc(lp, noteImprovement, &watch, MSG_MILPFEASIBLE | MSG_MILPBETTER);
  put_abortfunc(lp, workLimitReached, &watch);
}

void setTimeLimit(lprec* lp, double seconds) {
  const double whole = std::ceil(std::isnan(seconds) ? 1.0 : std::clamp(seconds, 1.0, 1e6));
  set_timeout(lp, long(whole));
}

bool objectiveAtInfinity(lprec* lp) { return std::abs(get_objective(lp)) >= 0.1 * get_infinite(lp); }

}  // namespace fcql
