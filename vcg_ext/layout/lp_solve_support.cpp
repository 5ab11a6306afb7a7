#include "layout/lp_solve_support.h"

#include <algorithm>
#include <cmath>

namespace fcql {
namespace {

void __WINAPI noteImprovement(lprec*, void* handle, int) {
  auto* watch = static_cast<StallWatch*>(handle);
  watch->haveSolution = true;
  watch->lastImprovement = std::chrono::steady_clock::now();
}

int __WINAPI stallReached(lprec*, void* handle) {
  auto* watch = static_cast<StallWatch*>(handle);
  if (!watch->haveSolution) return FALSE;
  const double idle = std::chrono::duration<double>(std::chrono::steady_clock::now() - watch->lastImprovement).count();
  if (idle < watch->limitSeconds) return FALSE;
  watch->stopped = true;
  return TRUE;
}

}  // namespace

void watchForStall(lprec* lp, StallWatch& watch) {
  if (!(watch.limitSeconds > 0)) return;
  put_msgfunc(lp, noteImprovement, &watch, MSG_MILPFEASIBLE | MSG_MILPBETTER);
  put_abortfunc(lp, stallReached, &watch);
}

void setTimeLimit(lprec* lp, double seconds) {
  const double whole = std::ceil(std::isnan(seconds) ? 1.0 : std::clamp(seconds, 1.0, 1e6));
  set_timeout(lp, long(whole));
}

bool objectiveAtInfinity(lprec* lp) { return std::abs(get_objective(lp)) >= 0.1 * get_infinite(lp); }

}  // namespace fcql
