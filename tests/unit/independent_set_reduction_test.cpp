#include "layout/independent_set_reduction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace fcql;

namespace {

using Rows = std::vector<std::vector<int>>;

/// The heaviest selection of variables with at most one per row, by trying every subset of
/// the variables not fixed to zero.
double bestSelection(const Rows& rows, const std::vector<double>& weight, const std::vector<char>& fixedToZero) {
  const int n = int(weight.size());
  double best = 0;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    bool ok = true;
    for (int v = 0; v < n && ok; ++v) ok = !((mask >> v) & 1) || !fixedToZero[v];
    for (const auto& row : rows) {
      int taken = 0;
      for (int v : row) taken += (mask >> v) & 1;
      ok = ok && taken <= 1;
    }
    if (!ok) continue;
    double value = 0;
    for (int v = 0; v < n; ++v)
      if ((mask >> v) & 1) value += weight[v];
    best = std::max(best, value);
  }
  return best;
}

}  // namespace

TEST(IndependentSetReduction, LeavesOutAVariableWhoseNeighbourDominatesIt) {
  // Rows {0, 1}, {1, 2}: 0's only neighbour is 1, so N[0] = {0, 1} ⊆ N[1] = {0, 1, 2}. When 0
  // weighs at least as much as 1, 0 can replace 1 in any selection (and frees 2 as well) ...
  const Rows rows = {{0, 1}, {1, 2}};
  DominationResult r = removeDominatedVariables(rows, {1.5, 1.0, 1.0});
  EXPECT_EQ(r.fixedToZero, (std::vector<char>{0, 1, 0}));
  // ... but not when 1 is heavier: the rule only compares single neighbours.
  r = removeDominatedVariables(rows, {1.0, 1.5, 1.0});
  EXPECT_EQ(r.fixedToZero, (std::vector<char>{0, 0, 0}));
  // Equal twins (same neighbours, same weight): exactly one of them stays.
  r = removeDominatedVariables({{0, 1}}, {2.0, 2.0});
  EXPECT_EQ(r.fixed, 1);
}

TEST(IndependentSetReduction, KeepsTheOptimumOnRandomPrograms) {
  // Random "at most one" rows over 14 variables with few distinct weights (ties are where a
  // careless rule would drop both of two twins): the optimum over the variables kept equals
  // the optimum over all of them, and something is left out in most programs.
  std::mt19937 random(7);
  int reducedPrograms = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 14;
    std::vector<double> weight(n);
    for (double& w : weight) w = 1 + int(random() % 4);
    Rows rows;
    const int numRows = 4 + int(random() % 10);
    for (int r = 0; r < numRows; ++r) {
      std::vector<int> row;
      for (int v = 0; v < n; ++v)
        if (random() % 4 == 0) row.push_back(v);
      if (row.size() >= 2) rows.push_back(row);
    }
    const DominationResult reduced = removeDominatedVariables(rows, weight);
    const std::vector<char> none(n, 0);
    ASSERT_DOUBLE_EQ(bestSelection(rows, weight, reduced.fixedToZero), bestSelection(rows, weight, none))
        << "trial " << trial;
    reducedPrograms += reduced.fixed > 0;
  }
  EXPECT_GE(reducedPrograms, 30);
}
