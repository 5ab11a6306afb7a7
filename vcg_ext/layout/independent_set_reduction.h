// Exact reductions for the 0-1 program of separatrix selection. The program is a maximum-
// weight independent set: variables are vertices, two variables in a common "at most one"
// row are adjacent. A variable u can be fixed to 0 when a neighbour v weighs at least as
// much and every neighbour of v is u or a neighbour of u (N[v] ⊆ N[u]): in any solution
// holding u, v can take u's place. Fixing variables this way keeps an optimal solution
// (the reduced program's optimum is the program's), and it shrinks what lp_solve must solve
// (bench/RESULTS.md has the dragon's figures).
#pragma once

#include <vector>

namespace fcql {

struct DominationResult {
  std::vector<char> fixedToZero;  ///< per variable: 1 if it can be left out
  int fixed = 0;
  int rounds = 0;  ///< sweeps over all variables until nothing changed
};

/// `rows`: "at most one of these" sets of variables in [0, weight.size()), each without
/// repeats. Removes dominated variables repeatedly until none is left (a variable
/// left out can make another one dominated). Deterministic: variables are visited in order.
DominationResult removeDominatedVariables(const std::vector<std::vector<int>>& rows, const std::vector<double>& weight);

}  // namespace fcql
