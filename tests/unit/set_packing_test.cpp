#include "solver/set_packing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace fcql;

namespace {

using Rows = std::vector<std::vector<int>>;

bool feasible(const Rows& rows, const std::vector<char>& chosen) {
  for (const auto& row : rows) {
    int taken = 0;
    for (int j : row) taken += chosen[j];
    if (taken > 1) return false;
  }
  return true;
}

double value(const std::vector<double>& weight, const std::vector<char>& chosen) {
  double v = 0;
  for (std::size_t j = 0; j < weight.size(); ++j) v += chosen[j] ? weight[j] : 0;
  return v;
}

/// The heaviest selection with at most one variable per row, by trying every subset.
double bestByBruteForce(const Rows& rows, const std::vector<double>& weight) {
  const int n = int(weight.size());
  double best = 0;
  std::vector<char> chosen(n);
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    for (int j = 0; j < n; ++j) chosen[j] = (mask >> j) & 1;
    if (feasible(rows, chosen)) best = std::max(best, value(weight, chosen));
  }
  return best;
}

/// The LP relaxation's optimum with every row, by lp_solve through IntegerProgram.
double relaxationOptimum(const Rows& rows, const std::vector<double>& weight) {
  IntegerProgram lp;
  lp.setMaximize(true);
  for (double w : weight) lp.addVariable(0, 1, false, w);
  for (const auto& row : rows) {
    std::vector<std::pair<int, double>> terms;
    for (int j : row) terms.push_back({j, 1.0});
    lp.addConstraint(terms, IntegerProgram::Sense::LessEqual, 1);
  }
  const auto r = lp.solve(10);
  EXPECT_EQ(r.status, IntegerProgram::Status::Optimal) << r.message;
  return r.objective;
}

/// `cycles` disjoint cycles of 5 variables of weight 1, one row per edge: the relaxation puts
/// every variable at 1/2 (2.5 per cycle) where a selection holds at most 2 per cycle.
Rows oddCycles(int cycles) {
  Rows rows;
  for (int c = 0; c < cycles; ++c)
    for (int i = 0; i < 5; ++i) rows.push_back({5 * c + i, 5 * c + (i + 1) % 5});
  return rows;
}

/// A random program of `n` variables weighing 0.2–3 and `numRows` rows of 2 to `maxSize`
/// variables drawn from a band of `band` consecutive ones (conflicts are local on a surface).
void bandedProgram(unsigned seed, int n, int numRows, int band, int maxSize, std::vector<double>& weight, Rows& rows) {
  std::mt19937 random(seed);
  weight.resize(n);
  for (double& w : weight) w = std::uniform_real_distribution<double>(0.2, 3.0)(random);
  rows.clear();
  for (int r = 0; r < numRows; ++r) {
    const int first = std::uniform_int_distribution<int>(0, n - band)(random);
    std::vector<int> vars;
    const int size = std::uniform_int_distribution<int>(2, maxSize)(random);
    while (int(vars.size()) < size) {
      const int j = first + std::uniform_int_distribution<int>(0, band - 1)(random);
      if (std::find(vars.begin(), vars.end(), j) == vars.end()) vars.push_back(j);
    }
    std::sort(vars.begin(), vars.end());
    rows.push_back(vars);
  }
}

}  // namespace

TEST(SetPacking, MatchesBruteForceOnRandomPrograms) {
  // Random rows of 2–4 variables over 14 variables with few distinct weights, sparse and
  // dense: every result is a feasible selection whose value is reported right, within the
  // relative gap of the optimum and never above the LP bound, which is the LP relaxation's
  // optimum with every row although lp_solve saw only the violated ones. Every step of the
  // method runs on some of these programs.
  std::mt19937 random(11);
  int fractionalPrograms = 0, branchAndBound = 0, improved = 0, fewerRows = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const int n = 14;
    const int numRows = 6 + trial % 20;
    std::vector<double> weight(n);
    for (double& w : weight) w = 1 + std::uniform_int_distribution<int>(0, 3)(random) * 0.5;
    Rows rows;
    for (int r = 0; r < numRows; ++r) {
      std::vector<int> vars(n);
      for (int j = 0; j < n; ++j) vars[j] = j;
      std::shuffle(vars.begin(), vars.end(), random);
      vars.resize(std::uniform_int_distribution<int>(2, 4)(random));
      std::sort(vars.begin(), vars.end());
      rows.push_back(vars);
    }
    SetPackingOptions options;
    options.relativeGap = 1e-9;
    const SetPackingResult r = solveSetPacking(weight, rows, options);
    ASSERT_EQ(r.status, IntegerProgram::Status::Optimal) << r.message;
    ASSERT_EQ(int(r.chosen.size()), n);
    EXPECT_TRUE(feasible(rows, r.chosen)) << "trial " << trial;
    EXPECT_NEAR(r.objective, value(weight, r.chosen), 1e-9);
    const double best = bestByBruteForce(rows, weight);
    EXPECT_NEAR(r.objective, best, 1e-6) << "trial " << trial << ": " << r.message;
    EXPECT_NEAR(r.bound, relaxationOptimum(rows, weight), 1e-6) << "trial " << trial;
    EXPECT_GE(r.bound, best - 1e-6);
    EXPECT_LE(r.rowsInRelaxation, int(rows.size()));
    fractionalPrograms += r.fractional > 0;
    branchAndBound += r.branchAndBound;
    improved += r.improvedByBranchAndBound;
    fewerRows += r.rowsInRelaxation < int(rows.size());
  }
  EXPECT_GT(fractionalPrograms, 10);
  EXPECT_GT(branchAndBound, 0);
  EXPECT_GT(improved, 0) << "relax and fix alone is not optimal on every program";
  EXPECT_GT(fewerRows, 60) << "the relaxation needs only some of the rows";
}

TEST(SetPacking, TheRelaxationWithRowsAndVariablesAddedLazilyIsTheWholeRelaxation) {
  // 1200 variables in rows of 2–6 neighbours (a band, as conflicts are local on a surface):
  // the relaxation lp_solve solves with only the rows and variables it needs has the optimum
  // of the relaxation with all of them, and it did need fewer of both.
  const int n = 1200;
  std::vector<double> weight;
  Rows rows;
  bandedProgram(5, n, 1800, 40, 6, weight, rows);
  SetPackingOptions options;
  options.stallNodes = 200;
  const SetPackingResult r = solveSetPacking(weight, rows, options);
  ASSERT_TRUE(r.hasSolution()) << r.message;
  EXPECT_NEAR(r.bound, relaxationOptimum(rows, weight), 1e-6);
  EXPECT_LT(r.rowsInRelaxation, int(rows.size()));
  EXPECT_LT(r.columnsInRelaxation, n);
  EXPECT_GT(r.relaxationRounds, 3);
  EXPECT_TRUE(feasible(rows, r.chosen));
  EXPECT_LE(r.objective, r.bound + 1e-9);
  EXPECT_NEAR(r.objective, value(weight, r.chosen), 1e-9);
}

TEST(SetPacking, AnOddCycleGoesThroughEveryStep) {
  // One 5-cycle: all five variables at 1/2 in the relaxation (bound 2.5), one fractional part,
  // solved exactly to 2; the 20% gap to the bound sends it to branch and bound, which proves
  // that nothing better exists.
  const Rows rows = oddCycles(1);
  const SetPackingResult r = solveSetPacking(std::vector<double>(5, 1.0), rows, SetPackingOptions{});
  ASSERT_EQ(r.status, IntegerProgram::Status::Optimal) << r.message;
  EXPECT_NEAR(r.bound, 2.5, 1e-9);
  EXPECT_EQ(r.fractional, 5);
  EXPECT_EQ(r.fractionalParts, 1);
  EXPECT_TRUE(r.branchAndBound);
  EXPECT_TRUE(r.warmStarted) << "branch and bound starts from the relaxation's basis";
  EXPECT_FALSE(r.improvedByBranchAndBound);
  EXPECT_NEAR(r.objective, 2, 1e-9);
  EXPECT_TRUE(feasible(rows, r.chosen));
}

TEST(SetPacking, AnIntegralRelaxationIsTheOptimum) {
  // A path of rows {0,1}, {1,2}, {2,3} with a heavy middle: the relaxation takes 1 and 3
  // (or 0 and 2), integral, so no branch and bound is needed.
  const Rows rows = {{0, 1}, {1, 2}, {2, 3}};
  const SetPackingResult r = solveSetPacking({1, 3, 1, 2}, rows, SetPackingOptions{});
  ASSERT_EQ(r.status, IntegerProgram::Status::Optimal) << r.message;
  EXPECT_EQ(r.fractional, 0);
  EXPECT_FALSE(r.branchAndBound);
  EXPECT_EQ(r.chosen, (std::vector<char>{0, 1, 0, 1}));
  EXPECT_NEAR(r.objective, 5, 1e-9);
}

TEST(SetPacking, BranchAndBoundStopsWhenItFindsNothingBetter) {
  // 150 disjoint 5-cycles: step 2 finds the optimum (2 per cycle) but the LP bound stays 25%
  // above it, and proving that takes branch and bound far longer than any test may run. The
  // stall limit, counted from step 2's selection, stops it.
  const int cycles = 150;
  const Rows rows = oddCycles(cycles);
  SetPackingOptions options;
  options.stallNodes = 200;
  options.timeLimitSeconds = 120;
  const SetPackingResult r = solveSetPacking(std::vector<double>(5 * cycles, 1.0), rows, options);
  ASSERT_EQ(r.status, IntegerProgram::Status::Stalled) << r.message;
  ASSERT_TRUE(r.hasSolution());
  EXPECT_TRUE(r.branchAndBound);
  EXPECT_NEAR(r.objective, 2 * cycles, 1e-9);
  EXPECT_NEAR(r.bound, 2.5 * cycles, 1e-6);
  EXPECT_TRUE(feasible(rows, r.chosen));
  EXPECT_NE(r.message.find("not proven optimal"), std::string::npos) << r.message;
}

TEST(SetPacking, TheGreedySelectionTakesTheHeaviestFreeVariableFirst) {
  const Rows rows = {{0, 1}, {1, 2}};
  EXPECT_EQ(greedyPacking({1, 3, 1}, rows), (std::vector<char>{0, 1, 0}));
  EXPECT_EQ(greedyPacking({2, 1, 2}, rows), (std::vector<char>{1, 0, 1}));
  EXPECT_EQ(greedyPacking({1, 1, 1}, rows), (std::vector<char>{1, 0, 1})) << "ties: lower index first";
  EXPECT_EQ(greedyPacking({1, 1, 1, 5}, rows), (std::vector<char>{1, 0, 1, 1})) << "a variable in no row is taken";
  EXPECT_THROW(greedyPacking({1, 1}, {{0, 0}}), std::invalid_argument);
}

TEST(SetPacking, TheWeightsUnitsDoNotMatter) {
  // The same random program with its weights scaled by 1e-12 and 1e12: the same selection, and
  // objective and bound scaled alike (lp_solve's tolerances are absolute; the solver is not).
  const int n = 300;
  std::vector<double> weight;
  Rows rows;
  bandedProgram(3, n, 450, 20, 2, weight, rows);
  SetPackingOptions options;
  options.stallNodes = 200;
  const SetPackingResult base = solveSetPacking(weight, rows, options);
  ASSERT_TRUE(base.hasSolution()) << base.message;
  for (double scale : {1e-12, 1e12}) {
    std::vector<double> scaled(weight);
    for (double& w : scaled) w *= scale;
    const SetPackingResult r = solveSetPacking(scaled, rows, options);
    ASSERT_TRUE(r.hasSolution()) << r.message;
    EXPECT_EQ(r.chosen, base.chosen) << "scale " << scale;
    EXPECT_NEAR(r.objective / scale, base.objective, 1e-9 * base.objective);
    EXPECT_NEAR(r.bound / scale, base.bound, 1e-6 * base.bound);
  }
}

TEST(SetPacking, SmallAndUnconstrainedPrograms) {
  // One variable, no row; variables in no row beside constrained ones; rows of one variable.
  SetPackingResult r = solveSetPacking({2.0}, {}, SetPackingOptions{});
  ASSERT_EQ(r.status, IntegerProgram::Status::Optimal) << r.message;
  EXPECT_EQ(r.chosen, (std::vector<char>{1}));
  EXPECT_NEAR(r.objective, 2, 1e-12);
  r = solveSetPacking({1, 2, 3, 4}, {{0, 1}, {2}}, SetPackingOptions{});
  ASSERT_EQ(r.status, IntegerProgram::Status::Optimal) << r.message;
  EXPECT_EQ(r.chosen, (std::vector<char>{0, 1, 1, 1}));
  EXPECT_NEAR(r.objective, 9, 1e-9);
}

TEST(SetPacking, BadInputIsRefused) {
  EXPECT_THROW(solveSetPacking({1, 1}, {{0, 2}}, SetPackingOptions{}), std::invalid_argument);
  EXPECT_THROW(solveSetPacking({1, 1}, {{0, 0}}, SetPackingOptions{}), std::invalid_argument);
  EXPECT_THROW(solveSetPacking({1, 0}, {{0, 1}}, SetPackingOptions{}), std::invalid_argument);
  EXPECT_THROW(solveSetPacking({1, std::nan("")}, {{0, 1}}, SetPackingOptions{}), std::invalid_argument);
  const SetPackingResult empty = solveSetPacking({}, {}, SetPackingOptions{});
  EXPECT_EQ(empty.status, IntegerProgram::Status::Optimal);
  EXPECT_TRUE(empty.chosen.empty());
}
