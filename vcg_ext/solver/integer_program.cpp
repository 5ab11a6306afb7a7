#include "solver/integer_program.h"

#include "solver/lp_solve_support.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace fcql {

int IntegerProgram::addVariable(double lower, double upper, bool integer, double objective) {
  if (!(lower <= upper)) throw std::invalid_argument("IntegerProgram: variable bounds are empty");
  lower_.push_back(lower);
  upper_.push_back(upper);
  integer_.push_back(integer);
  objective_.push_back(objective);
  return int(lower_.size()) - 1;
}

void IntegerProgram::setObjective(int variable, double coefficient) { objective_.at(variable) = coefficient; }

void IntegerProgram::addConstraint(const std::vector<std::pair<int, double>>& terms, Sense sense, double rhs) {
  for (const auto& t : terms)
    if (t.first < 0 || t.first >= numVariables()) throw std::out_of_range("IntegerProgram: constraint on an unknown variable");
  rows_.push_back({terms, sense, rhs});
}

const char* toString(IntegerProgram::Status status) {
  switch (status) {
    case IntegerProgram::Status::Optimal: return "optimal";
    case IntegerProgram::Status::TimeLimit: return "time limit reached, best solution found kept";
    case IntegerProgram::Status::Stalled: return "best solution stopped improving, kept";
    case IntegerProgram::Status::WorkLimit: return "node budget reached, best solution found kept";
    case IntegerProgram::Status::Infeasible: return "infeasible";
    case IntegerProgram::Status::Unbounded: return "unbounded";
    default: return "failed";
  }
}

namespace {

constexpr double kMinRelaxationSeconds = 60;
/// Rounds of solveByRounding that round one variable per constraint; then all the rest at once.
constexpr int kGradualRounds = 50;

/// The result for a program without variables: nothing to solve.
IntegerProgram::Result emptyProgramResult() {
  IntegerProgram::Result result;
  result.status = IntegerProgram::Status::Optimal;
  result.message = "empty program";
  return result;
}

}  // namespace

/// The program as an lp_solve model (integer flags dropped when `relaxed`); null with
/// `message` set if lp_solve refuses it.
LpModel IntegerProgram::buildModel(bool relaxed, std::string& message) const {
  const int n = numVariables();
  LpModel lp(make_lp(0, n), delete_lp);
  if (!lp) {
    message = "lp_solve could not create the model (out of memory?)";
    return lp;
  }
  set_verbose(lp.get(), NEUTRAL);
  std::vector<int> cols;
  std::vector<double> vals;
  // Objective and bounds.
  for (int j = 0; j < n; ++j) {
    cols.push_back(j + 1);
    vals.push_back(objective_[j]);
  }
  set_obj_fnex(lp.get(), n, vals.data(), cols.data());
  if (maximize_) set_maxim(lp.get());
  else set_minim(lp.get());
  for (int j = 0; j < n; ++j) {
    set_bounds(lp.get(), j + 1, std::isinf(lower_[j]) ? -get_infinite(lp.get()) : lower_[j],
               std::isinf(upper_[j]) ? get_infinite(lp.get()) : upper_[j]);
    if (integer_[j] && !relaxed) set_int(lp.get(), j + 1, TRUE);
  }
  set_add_rowmode(lp.get(), TRUE);
  for (const Row& r : rows_) {
    cols.clear();
    vals.clear();
    for (const auto& t : r.terms) {
      cols.push_back(t.first + 1);
      vals.push_back(t.second);
    }
    int type = r.sense == Sense::LessEqual ? LE : (r.sense == Sense::GreaterEqual ? GE : EQ);
    if (!add_constraintex(lp.get(), int(cols.size()), vals.data(), cols.data(), type, r.rhs)) {
      message = "lp_solve rejected a constraint";
      return LpModel(nullptr, delete_lp);
    }
  }
  set_add_rowmode(lp.get(), FALSE);
  set_presolve(lp.get(), PRESOLVE_NONE, get_presolveloops(lp.get()));
  return lp;
}

IntegerProgram::Result IntegerProgram::solve(double timeLimitSeconds) const {
  const int n = numVariables();
  if (n == 0) return emptyProgramResult();
  Result result;
  auto start = std::chrono::steady_clock::now();
  LpModel lp = buildModel(false, result.message);
  if (!lp) return result;
  setTimeLimit(lp.get(), timeLimitSeconds);
  set_mip_gap(lp.get(), FALSE, relativeGap_);
  if (branchDownFirst_) set_bb_floorfirst(lp.get(), BRANCH_FLOOR);
  BranchAndBoundWatch watch;
  watch.stallNodes = stallNodes_;
  watch.nodeLimit = nodeLimit_;
  watchBranchAndBound(lp.get(), watch);
  int ret = ::solve(lp.get());
  result.nodes = long(get_total_nodes(lp.get()));
  if (watch.stopped() && (ret == SUBOPTIMAL || ret == USERABORT) && get_solutioncount(lp.get()) > 0) {
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.status = watch.stalled ? Status::Stalled : Status::WorkLimit;
    result.values.assign(n, 0.0);
    get_variables(lp.get(), result.values.data());
    result.objective = get_objective(lp.get());
    result.message = watch.stalled ? "lp_solve's best solution did not improve for " + std::to_string(stallNodes_) +
                                         " branch-and-bound nodes; it is kept (not proven optimal)"
                                   : "lp_solve reached its budget of " + std::to_string(nodeLimit_) +
                                         " branch-and-bound nodes; the best solution found is kept";
    return result;
  }
  if (watch.stopped() && ret == USERABORT) {  // the budget ran out before any solution
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.status = Status::Failed;
    result.message = "lp_solve reached its budget of " + std::to_string(nodeLimit_) +
                     " branch-and-bound nodes before finding any solution";
    return result;
  }
  // Neither work limit stopped it: SUBOPTIMAL and TIMEOUT mean the safety time limit.
  result.timeLimitReached = ret == SUBOPTIMAL || ret == TIMEOUT;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto readSolution = [&]() {
    result.values.assign(n, 0.0);
    get_variables(lp.get(), result.values.data());
    result.objective = get_objective(lp.get());
  };
  switch (ret) {
    case OPTIMAL:
    case PRESOLVED:
      result.status = Status::Optimal;
      readSolution();
      if (objectiveAtInfinity(lp.get())) {
        result.status = Status::Unbounded;
        result.values.clear();
        result.message = "the integer program is unbounded";
      }
      break;
    case SUBOPTIMAL:
      result.status = Status::TimeLimit;
      readSolution();
      result.message = "lp_solve reached the time limit (a safety stop: this result depends on the machine's speed); "
                       "the best solution found is kept";
      break;
    case TIMEOUT:
      // lp_solve reports TIMEOUT both with and without an improved solution.
      if (get_solutioncount(lp.get()) > 0) {
        result.status = Status::TimeLimit;
        readSolution();
        result.message = "lp_solve reached the time limit (a safety stop: this result depends on the machine's "
                         "speed); the best solution found is kept";
      } else {
        result.status = Status::Failed;
        result.message = "lp_solve reached the time limit before finding any solution";
      }
      break;
    case INFEASIBLE:
      result.status = Status::Infeasible;
      result.message = "the integer program is infeasible";
      break;
    case UNBOUNDED:
      result.status = Status::Unbounded;
      result.message = "the integer program is unbounded";
      break;
    case NOMEMORY:
      result.message = "lp_solve ran out of memory";
      break;
    default:
      result.message = "lp_solve failed with code " + std::to_string(ret);
  }
  return result;
}

IntegerProgram::Result IntegerProgram::solveByRounding(double timeLimitSeconds) const {
  const int n = numVariables();
  if (n == 0) return emptyProgramResult();
  Result result;
  // The integers each integer variable may take: none means no solution at all.
  std::vector<double> lowest(n), highest(n);
  for (int j = 0; j < n; ++j) {
    if (!integer_[j]) continue;
    lowest[j] = std::ceil(lower_[j] - 1e-9);
    highest[j] = std::floor(upper_[j] + 1e-9);
    if (lowest[j] > highest[j]) {
      result.status = Status::Infeasible;
      result.message = "an integer variable's bounds hold no integer";
      return result;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  LpModel lp = buildModel(true, result.message);
  if (!lp) return result;
  std::vector<char> fixed(n, 0);
  std::vector<double> x(n);
  // Per integer variable: the constraints it shares with other integer variables.
  std::vector<std::vector<int>> coupling(n);
  for (int row = 0; row < numConstraints(); ++row) {
    int integers = 0;
    for (const auto& t : rows_[row].terms) integers += integer_[t.first] ? 1 : 0;
    if (integers < 2) continue;
    for (const auto& t : rows_[row].terms)
      if (integer_[t.first]) coupling[t.first].push_back(row);
  }
  std::vector<int> rowBatch(numConstraints(), 0);
  int batch = 0;
  auto fix = [&](int j, double value) {
    fixed[j] = 1;
    const double r = std::clamp(value, lowest[j], highest[j]);
    set_bounds(lp.get(), j + 1, r, r);
  };
  for (int round = 1;; ++round) {
    // Each solve may take the whole limit, and at least kMinRelaxationSeconds: this is the
    // fallback when branch and bound found nothing in time, and a relaxation cut short leaves
    // nothing to round (the dragon's soft side-length programs take lp_solve 5–7 s each).
    // Once the limit is spent, everything left is rounded at once and one more solve
    // finishes the job.
    setTimeLimit(lp.get(), std::max(timeLimitSeconds, kMinRelaxationSeconds));
    const int ret = ::solve(lp.get());  // after the first round, from the last basis
    const bool unbounded =
        ret == UNBOUNDED || ((ret == OPTIMAL || ret == SUBOPTIMAL || ret == PRESOLVED) && objectiveAtInfinity(lp.get()));
    if (unbounded) {
      result.status = Status::Unbounded;
      result.message = "the integer program is unbounded";
    } else if (ret == INFEASIBLE) {
      result.status = Status::Infeasible;
      result.message = round == 1 ? "the integer program is infeasible (so is its LP relaxation)"
                                  : "rounding the LP relaxation made it infeasible (no solution found this way)";
    } else if (ret != OPTIMAL && ret != SUBOPTIMAL && ret != PRESOLVED) {
      result.status = Status::Failed;
      result.message = "lp_solve failed on the LP relaxation (code " + std::to_string(ret) + ")";
    }
    if (unbounded || (ret != OPTIMAL && ret != SUBOPTIMAL && ret != PRESOLVED)) {
      result.seconds = elapsed();
      return result;
    }
    get_variables(lp.get(), x.data());
    // Values already integral are kept; the others are rounded, nearest to an integer first
    // (all of them once the time is up), and the relaxation solved again.
    std::vector<std::pair<double, int>> fractional;
    for (int j = 0; j < n; ++j) {
      if (!integer_[j] || fixed[j]) continue;
      const double r = std::round(x[j]);
      if (std::abs(x[j] - r) <= 1e-6) fix(j, r);
      else fractional.push_back({std::abs(x[j] - r), j});
    }
    if (fractional.empty()) {
      result.values = x;
      for (int j = 0; j < n; ++j)
        if (integer_[j]) result.values[j] = std::clamp(std::round(x[j]), lowest[j], highest[j]);
      result.objective = get_objective(lp.get());
      // Integral from the start: the relaxation's optimum, hence the program's.
      result.status = round == 1 && ret != SUBOPTIMAL ? Status::Optimal : Status::TimeLimit;
      result.message = round == 1 ? "the LP relaxation's solution is integral"
                                  : "the LP relaxation rounded in " + std::to_string(round) +
                                        " rounds (a feasible solution, not proven optimal)";
      result.seconds = elapsed();
      return result;
    }
    std::sort(fractional.begin(), fractional.end());
    // Two variables of one constraint are not rounded in the same round: the relaxation,
    // solved again, moves the others of the constraint to follow the first.
    // After kGradualRounds rounds (counted, so that the result is the same on any machine), or
    // once the safety time limit is spent, everything left is rounded at once.
    const bool outOfTime = elapsed() >= timeLimitSeconds;
    result.timeLimitReached = result.timeLimitReached || outOfTime;
    const bool allNow = outOfTime || round >= kGradualRounds;
    ++batch;
    for (const auto& f : fractional) {
      const int j = f.second;
      bool free = true;
      for (int row : coupling[j]) free = free && rowBatch[row] != batch;
      if (!free && !allNow) continue;
      for (int row : coupling[j]) rowBatch[row] = batch;
      fix(j, std::round(x[j]));
    }
  }
}

}  // namespace fcql
