#include "solver/set_packing.h"

#include "solver/lp_solve_support.h"
#include "util/union_find.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>
#include <stdexcept>

namespace fcql {
namespace {

/// Step 2's parts stop after this many times options.stallNodes nodes without a better solution.
constexpr long kPartStallFactor = 200;

constexpr double kViolation = 1e-7;  // a row summing to more than 1 + this is violated
constexpr double kIntegral = 1e-6;   // a relaxed value this close to 0 or 1 is taken as such
constexpr double kReducedCost = 1e-9;  // a variable left out prices in above this
// Variables entering the relaxation per round of pricing: on the dragon's largest part
// (10.8K variables) 100–500 give 0.9–1.3 s against 2 s with every variable in.
constexpr std::size_t kColumnsPerRound = 200;

using Clock = std::chrono::steady_clock;

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g%%", 100 * fraction);
  return text;
}

void validate(const std::vector<double>& weight, const std::vector<std::vector<int>>& rows) {
  const int n = int(weight.size());
  for (double w : weight)
    if (!(w > 0) || !std::isfinite(w)) throw std::invalid_argument("set packing: weights must be positive and finite");
  std::vector<int> seenInRow(n, -1);
  for (int r = 0; r < int(rows.size()); ++r)
    for (int j : rows[r]) {
      if (j < 0 || j >= n) throw std::invalid_argument("set packing: a row names an unknown variable");
      if (seenInRow[j] == r) throw std::invalid_argument("set packing: a row names a variable twice");
      seenInRow[j] = r;
    }
}

/// For each variable, the rows it is in.
std::vector<std::vector<int>> rowsOfVariables(int numVariables, const std::vector<std::vector<int>>& rows) {
  std::vector<std::vector<int>> rowsOf(numVariables);
  for (int r = 0; r < int(rows.size()); ++r)
    for (int j : rows[r]) rowsOf[j].push_back(r);
  return rowsOf;
}

/// Takes the variables not chosen yet whose rows hold no chosen one, heaviest first (ties:
/// lower index first); `rowTaken` counts the chosen variables of each row and is kept up to
/// date. Returns the variables taken, in the order they were.
std::vector<int> takeFreeVariables(const std::vector<double>& weight, const std::vector<std::vector<int>>& rowsOf,
                                   std::vector<int>& rowTaken, std::vector<char>& chosen) {
  std::vector<int> order(weight.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weight[a] > weight[b]; });
  std::vector<int> taken;
  for (int j : order) {
    if (chosen[j]) continue;
    bool free = true;
    for (int r : rowsOf[j]) free = free && rowTaken[r] == 0;
    if (!free) continue;
    chosen[j] = 1;
    taken.push_back(j);
    for (int r : rowsOf[j]) ++rowTaken[r];
  }
  return taken;
}

/// Sorts (value, index) pairs by value, largest first, then by index: the same order whatever
/// the sort does with ties.
void sortLargestFirst(std::vector<std::pair<double, int>>& items) {
  std::sort(items.begin(), items.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
}

/// The LP relaxation with its rows and columns added as they are needed (step 1). lp_solve
/// works on the variables of a greedy selection at first and on no row; then, each round,
/// either the violated rows enter (the most violated first, none sharing a positive variable
/// with one added before it in the round: the next solve would settle both with one change)
/// or, when none is violated, the variables whose reduced cost under the rows' duals is
/// positive (the largest first, at most kColumnsPerRound). When neither is left the values are
/// optimal for the whole relaxation: every row holds (all are checked) and the duals, 0 on the
/// rows left out, price every variable left out at 0 or less.
class LazyRelaxation {
public:
  LazyRelaxation(const std::vector<double>& weight, const std::vector<std::vector<int>>& rows)
      : weight_(weight), rows_(rows), rowInModel_(rows.size(), 0), columnOf_(weight.size(), 0),
        lp_(make_lp(0, 0), delete_lp) {
    const int n = int(weight.size());
    x_.assign(n, 0);
    lastRound_.assign(n, -1);
    rowsOf_ = rowsOfVariables(n, rows_);
    if (!lp_) return;
    set_verbose(lp_.get(), NEUTRAL);
    set_maxim(lp_.get());
    set_presolve(lp_.get(), PRESOLVE_DUALS, get_presolveloops(lp_.get()));  // for the pricing
    // The first columns: a greedy selection, feasible with every row.
    std::vector<int> rowTaken(rows_.size(), 0);
    std::vector<char> chosen(n, 0);
    for (int j : takeFreeVariables(weight_, rowsOf_, rowTaken, chosen)) addColumn(j);
  }

  lprec* model() { return lp_.get(); }
  const std::vector<double>& values() const { return x_; }
  int rounds() const { return rounds_; }
  int rowsInModel() const { return int(modelRows_.size()); }
  int columnsInModel() const { return int(modelColumns_.size()); }
  const std::vector<std::vector<int>>& rowsOf() const { return rowsOf_; }

  /// Solves until no row is violated and no column prices in; false with `message` set if
  /// lp_solve fails.
  bool solve(const std::function<double()>& secondsLeft, std::string& message) {
    if (!lp_) {
      message = "lp_solve could not create the model (out of memory?)";
      return false;
    }
    std::vector<double> values;
    for (;;) {
      if (failed_) {
        message = "lp_solve could not add a row or a variable to the LP relaxation (out of memory?)";
        return false;
      }
      setTimeLimit(lp_.get(), secondsLeft());
      const int ret = ::solve(lp_.get());  // after the first round, from the last basis
      if (ret != OPTIMAL && ret != PRESOLVED) {
        message = ret == TIMEOUT ? "lp_solve reached the time limit on the LP relaxation"
                                 : "lp_solve failed on the LP relaxation (code " + std::to_string(ret) + ")";
        return false;
      }
      values.assign(modelColumns_.size(), 0);
      get_variables(lp_.get(), values.data());
      std::fill(x_.begin(), x_.end(), 0.0);
      for (std::size_t c = 0; c < modelColumns_.size(); ++c) x_[modelColumns_[c]] = values[c];
      ++rounds_;
      if (!addViolatedRows() && !addPricedColumns()) return true;
      if (secondsLeft() <= 0) {
        message = "time limit reached on the LP relaxation (" + std::to_string(rounds_) + " rounds)";
        return false;
      }
    }
  }

  /// The whole program with every row and column, as a 0-1 program, starting from the
  /// relaxation's optimal basis: the rows it did without enter with their slacks basic, the
  /// columns it did without at 0, which keeps the basis optimal. Built anew in row-entry mode:
  /// adding the rest of the rows to the relaxation's model one by one costs lp_solve 0.9 s on
  /// the dragon. Null with `message` set if lp_solve fails.
  LpModel wholeProgram(std::string& message, bool& warmStarted) const {
    warmStarted = false;
    const int n = int(weight_.size()), m = int(rows_.size());
    LpModel lp(make_lp(0, n), delete_lp);
    if (!lp) {
      message = "lp_solve could not create the model (out of memory?)";
      return lp;
    }
    set_verbose(lp.get(), NEUTRAL);
    std::vector<int> cols(n);
    std::iota(cols.begin(), cols.end(), 1);
    set_obj_fnex(lp.get(), n, const_cast<double*>(weight_.data()), cols.data());
    set_maxim(lp.get());
    set_add_rowmode(lp.get(), TRUE);
    std::vector<double> ones;
    for (const auto& row : rows_) {
      cols.clear();
      for (int j : row) cols.push_back(j + 1);
      ones.assign(cols.size(), 1.0);
      if (!add_constraintex(lp.get(), int(cols.size()), ones.data(), cols.data(), LE, 1)) {
        message = "lp_solve could not build the whole program (out of memory?)";
        return LpModel(nullptr, delete_lp);
      }
    }
    set_add_rowmode(lp.get(), FALSE);
    for (int j = 1; j <= n; ++j) {
      set_bounds(lp.get(), j, 0, 1);
      set_int(lp.get(), j, TRUE);
    }
    // lp_solve numbers a model's variables rows first (1..rows), then columns; a basis lists
    // the basic ones and then the nonbasic ones, negative when at their lower bound.
    const int k = rowsInModel(), c = columnsInModel();
    std::vector<int> from(1 + k + c), to(1 + m + n);
    if (get_basis(lp_.get(), from.data(), TRUE)) {
      auto map = [&](int v) {
        const int a = std::abs(v);
        const int mapped = a <= k ? modelRows_[a - 1] + 1 : m + modelColumns_[a - k - 1] + 1;
        return v < 0 ? -mapped : mapped;
      };
      int at = 1;
      for (int i = 1; i <= k; ++i) to[at++] = map(from[i]);
      for (int r = 0; r < m; ++r)
        if (!rowInModel_[r]) to[at++] = r + 1;
      for (int i = k + 1; i <= k + c; ++i) to[at++] = map(from[i]);
      for (int j = 0; j < n; ++j)
        if (!columnOf_[j]) to[at++] = -(m + j + 1);
      warmStarted = set_basis(lp.get(), to.data(), TRUE);
    }
    if (!warmStarted) default_basis(lp.get());  // a refused basis may be left half written
    return lp;
  }

private:
  /// Variable j as a column of the model, with its entries in the rows already there.
  void addColumn(int j) {
    entries_.clear();
    for (int r : rowsOf_[j])
      if (rowInModel_[r]) entries_.push_back(rowInModel_[r]);
    std::sort(entries_.begin(), entries_.end());
    entries_.insert(entries_.begin(), 0);  // the objective
    values_.assign(entries_.size(), 1.0);
    values_[0] = weight_[j];
    if (!add_columnex(lp_.get(), int(entries_.size()), values_.data(), entries_.data())) {
      failed_ = true;
      return;
    }
    modelColumns_.push_back(j);
    columnOf_[j] = int(modelColumns_.size());
    set_bounds(lp_.get(), columnOf_[j], 0, 1);
  }

  /// Row r, with its entries in the columns already there.
  void addRow(int r) {
    entries_.clear();
    for (int j : rows_[r])
      if (columnOf_[j]) entries_.push_back(columnOf_[j]);
    std::sort(entries_.begin(), entries_.end());
    values_.assign(entries_.size(), 1.0);
    if (!add_constraintex(lp_.get(), int(entries_.size()), values_.data(), entries_.data(), LE, 1)) {
      failed_ = true;
      return;
    }
    modelRows_.push_back(r);
    rowInModel_[r] = int(modelRows_.size());
  }

  /// False if no row is violated.
  bool addViolatedRows() {
    violated_.clear();
    for (int r = 0; r < int(rows_.size()); ++r) {
      if (rowInModel_[r]) continue;
      double sum = 0;
      for (int j : rows_[r]) sum += x_[j];
      if (sum > 1 + kViolation) violated_.push_back({sum, r});
    }
    if (violated_.empty()) return false;
    sortLargestFirst(violated_);
    for (const auto& v : violated_) {
      const auto& row = rows_[v.second];
      bool clash = false;
      for (int j : row) clash = clash || (x_[j] > kIntegral && lastRound_[j] == rounds_);
      if (clash) continue;
      for (int j : row)
        if (x_[j] > kIntegral) lastRound_[j] = rounds_;
      addRow(v.second);
    }
    return true;
  }

  /// False if no variable left out has a positive reduced cost.
  bool addPricedColumns() {
    double* duals = nullptr;  // [0] the objective, then one per row of the model
    if (!get_ptr_dual_solution(lp_.get(), &duals) || !duals) {
      // Without duals nothing can be priced: every variable left out enters at once.
      const std::size_t before = modelColumns_.size();
      for (int j = 0; j < int(weight_.size()); ++j)
        if (!columnOf_[j]) addColumn(j);
      return modelColumns_.size() > before;
    }
    priced_.clear();
    for (int j = 0; j < int(weight_.size()); ++j) {
      if (columnOf_[j]) continue;
      double reduced = weight_[j];
      for (int r : rowsOf_[j])
        if (rowInModel_[r]) reduced -= duals[rowInModel_[r]];
      if (reduced > kReducedCost) priced_.push_back({reduced, j});
    }
    if (priced_.empty()) return false;
    sortLargestFirst(priced_);
    if (priced_.size() > kColumnsPerRound) priced_.resize(kColumnsPerRound);
    for (const auto& p : priced_) addColumn(p.second);
    return true;
  }

  const std::vector<double>& weight_;
  const std::vector<std::vector<int>>& rows_;
  std::vector<std::vector<int>> rowsOf_;
  std::vector<int> rowInModel_;  // 1 + its row in the model, 0 if not there
  std::vector<int> columnOf_;    // 1 + its column in the model, 0 if not there
  std::vector<int> modelRows_, modelColumns_;  // in the order they entered
  LpModel lp_;
  std::vector<double> x_;
  std::vector<int> lastRound_;  // the round in which a row holding the variable was added
  std::vector<std::pair<double, int>> violated_, priced_;
  std::vector<int> entries_;
  std::vector<double> values_;
  int rounds_ = 0;
  bool failed_ = false;  // lp_solve refused a row or a column: the model no longer matches
};

/// Step 2: variables at 1 in the relaxation `x` are taken, those at 0 left out, the fractional
/// rest is solved exactly by independent parts, and variables left free are then taken,
/// heaviest first. Counts the fractional variables and parts into `result`.
std::vector<char> fixByParts(const std::vector<double>& weight, const std::vector<std::vector<int>>& rows,
                             const std::vector<std::vector<int>>& rowsOf, const std::vector<double>& x,
                             const SetPackingOptions& options, const std::function<double()>& secondsLeft,
                             SetPackingResult& result) {
  const int n = int(weight.size());
  // 1 taken, 0 left out, 2 fractional.
  std::vector<char> state(n);
  for (int j = 0; j < n; ++j) state[j] = x[j] >= 1 - kIntegral ? 1 : (x[j] <= kIntegral ? 0 : 2);
  // A row holding a variable at 1 holds the others at 0 up to rounding noise: they stay out.
  for (const auto& row : rows) {
    int taken = -1;
    for (int j : row)
      if (state[j] == 1) {
        if (taken >= 0) state[j] = 0;  // cannot happen within lp_solve's tolerances
        else taken = j;
      }
    if (taken >= 0)
      for (int j : row)
        if (state[j] == 2) state[j] = 0;
  }
  UnionFind parts(n);
  for (const auto& row : rows) {
    int first = -1;
    for (int j : row) {
      if (state[j] != 2) continue;
      if (first < 0) first = j;
      else parts.unite(first, j);
    }
  }
  std::vector<std::vector<int>> members(n), rowsOfPart(n);
  for (int j = 0; j < n; ++j)
    if (state[j] == 2) members[parts.find(j)].push_back(j), ++result.fractional;
  for (int r = 0; r < int(rows.size()); ++r) {
    int fractional = 0, any = -1;
    for (int j : rows[r])
      if (state[j] == 2) ++fractional, any = j;
    if (fractional >= 2) rowsOfPart[parts.find(any)].push_back(r);
  }
  std::vector<char> chosen(n, 0);
  for (int j = 0; j < n; ++j) chosen[j] = state[j] == 1;
  std::vector<int> local(n, -1);
  for (int root = 0; root < n; ++root) {
    const auto& part = members[root];
    if (part.empty()) continue;
    ++result.fractionalParts;
    if (part.size() == 1) {
      chosen[part[0]] = 1;
      continue;
    }
    IntegerProgram ip;
    ip.setMaximize(true);
    ip.setRelativeGap(options.relativeGap);
    // The parts are small: lp_solve runs thousands of their nodes a second, so they get
    // kPartStallFactor times the stall of step 3's branch and bound on the whole program.
    ip.setStallNodes(options.stallNodes * kPartStallFactor);
    for (int j : part) local[j] = ip.addBinary(weight[j]);
    for (int r : rowsOfPart[root]) {
      std::vector<std::pair<int, double>> terms;
      for (int j : rows[r])
        if (state[j] == 2) terms.push_back({local[j], 1.0});
      ip.addConstraint(terms, IntegerProgram::Sense::LessEqual, 1.0);
    }
    if (secondsLeft() <= 0) {  // no time left (a safety stop): what can be taken is taken below
      result.timeLimitReached = true;
      continue;
    }
    const IntegerProgram::Result r = ip.solve(secondsLeft());
    result.timeLimitReached = result.timeLimitReached || r.timeLimitReached;
    if (r.hasSolution())
      for (int j : part) chosen[j] = r.values[local[j]] > 0.5;
    // else the part stays out: what can be taken is taken below
  }
  std::vector<int> rowTaken(rows.size(), 0);
  for (int r = 0; r < int(rows.size()); ++r)
    for (int j : rows[r]) rowTaken[r] += chosen[j];
  takeFreeVariables(weight, rowsOf, rowTaken, chosen);
  return chosen;
}

}  // namespace

std::vector<char> greedyPacking(const std::vector<double>& weight, const std::vector<std::vector<int>>& rows) {
  validate(weight, rows);
  std::vector<int> rowTaken(rows.size(), 0);
  std::vector<char> chosen(weight.size(), 0);
  takeFreeVariables(weight, rowsOfVariables(int(weight.size()), rows), rowTaken, chosen);
  return chosen;
}

SetPackingResult solveSetPacking(const std::vector<double>& weight, const std::vector<std::vector<int>>& rows,
                                 const SetPackingOptions& options) {
  validate(weight, rows);
  const int n = int(weight.size());
  SetPackingResult result;
  if (n == 0) {
    result.status = IntegerProgram::Status::Optimal;
    result.message = "empty program";
    return result;
  }
  const auto start = Clock::now();
  const std::function<double()> secondsLeft = [&] {
    return options.timeLimitSeconds - std::chrono::duration<double>(Clock::now() - start).count();
  };

  // lp_solve works on weights scaled to at most 1, so that its absolute tolerances (and the
  // pricing's) mean the same whatever the weights' units; objectives are reported unscaled.
  const double scale = *std::max_element(weight.begin(), weight.end());
  std::vector<double> unit(n);
  for (int j = 0; j < n; ++j) unit[j] = weight[j] / scale;

  // Step 1: the LP relaxation.
  LazyRelaxation relaxation(unit, rows);
  if (!relaxation.solve(secondsLeft, result.message)) {
    result.timeLimitReached = secondsLeft() <= 0;
    return result;
  }
  result.relaxationRounds = relaxation.rounds();
  result.rowsInRelaxation = relaxation.rowsInModel();
  result.columnsInRelaxation = relaxation.columnsInModel();
  result.bound = get_objective(relaxation.model()) * scale;

  // Step 2: relax and fix.
  result.chosen = fixByParts(unit, rows, relaxation.rowsOf(), relaxation.values(), options, secondsLeft, result);
  for (int j = 0; j < n; ++j) result.objective += result.chosen[j] ? weight[j] : 0;
  auto belowBound = [&] { return percent((result.bound - result.objective) / result.bound); };

  if (result.bound - result.objective <= options.relativeGap * result.bound) {
    result.status = IntegerProgram::Status::Optimal;
    result.message = result.fractional == 0
                         ? "the LP relaxation is integral"
                         : "the relaxation fixed where integral and its fractional rest solved by parts: within " +
                               percent(options.relativeGap) + " of the LP bound";
    return result;
  }

  if (secondsLeft() <= 0) {
    result.status = IntegerProgram::Status::TimeLimit;
    result.timeLimitReached = true;
    result.message = "the relaxation fixed by parts, " + belowBound() +
                     " below the LP bound; the safety time limit left no time to improve it";
    return result;
  }

  // Step 3: branch and bound on the whole, for a better selection than step 2's.
  result.branchAndBound = true;
  std::string failure;
  LpModel whole = relaxation.wholeProgram(failure, result.warmStarted);
  if (!whole) {
    result.status = IntegerProgram::Status::TimeLimit;
    result.message = "the relaxation fixed by parts, not improved: " + failure;
    return result;
  }
  lprec* lp = whole.get();
  set_mip_gap(lp, FALSE, options.relativeGap);
  set_obj_bound(lp, result.objective / scale);  // only better selections are accepted
  BranchAndBoundWatch watch;
  watch.stallNodes = options.stallNodes;
  watch.haveSolution = true;  // step 2's
  watchBranchAndBound(lp, watch);
  setTimeLimit(lp, secondsLeft());
  const int ret = ::solve(lp);
  bool discarded = false;  // branch and bound's selection broke a row (lp_solve's tolerances)
  if (get_solutioncount(lp) > 0 && (ret == OPTIMAL || ret == PRESOLVED || ret == SUBOPTIMAL || ret == TIMEOUT ||
                                    ret == USERABORT)) {
    std::vector<double> values(n);
    get_variables(lp, values.data());
    std::vector<char> better(n);
    double objective = 0;
    for (int j = 0; j < n; ++j) {
      better[j] = values[j] > 0.5;
      objective += better[j] ? weight[j] : 0;
    }
    bool feasible = true;
    for (const auto& row : rows) {
      int taken = 0;
      for (int j : row) taken += better[j];
      feasible = feasible && taken <= 1;
    }
    discarded = !feasible;
    if (feasible && objective > result.objective * (1 + 1e-9)) {
      result.chosen = better;
      result.objective = objective;
      result.improvedByBranchAndBound = true;
    }
  }
  const std::string what = result.improvedByBranchAndBound ? "branch and bound improved the relaxation fixed by parts"
                                                           : "the relaxation fixed by parts";
  if (discarded) {
    result.status = IntegerProgram::Status::TimeLimit;
    result.message = "the relaxation fixed by parts, " + belowBound() +
                     " below the LP bound; branch and bound's selection broke a row and was discarded";
  } else if (ret == OPTIMAL || ret == PRESOLVED || ret == INFEASIBLE) {  // INFEASIBLE: nothing better exists
    result.status = IntegerProgram::Status::Optimal;
    result.message = what + ": proven within " + percent(options.relativeGap) + " of the optimum by branch and bound";
  } else if (watch.stopped()) {
    result.status = IntegerProgram::Status::Stalled;
    result.message = what + ", " + belowBound() + " below the LP bound; branch and bound found nothing better in " +
                     std::to_string(options.stallNodes) + " nodes (not proven optimal)";
  } else {
    result.status = IntegerProgram::Status::TimeLimit;
    result.timeLimitReached = ret == TIMEOUT || ret == SUBOPTIMAL;
    result.message = what + ", " + belowBound() +
                     " below the LP bound; branch and bound stopped (" +
                     (ret == TIMEOUT || ret == SUBOPTIMAL ? std::string("the safety time limit")
                                                          : "lp_solve code " + std::to_string(ret)) +
                     ", not proven optimal)";
  }
  return result;
}

}  // namespace fcql
