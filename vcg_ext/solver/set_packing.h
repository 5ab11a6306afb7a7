// A 0-1 set-packing program, the form of the separatrix selection: maximise Σ w_j x_j over
// binary x with Σ_{j∈R} x_j ≤ 1 for every row R. Solved with lp_solve in three steps:
//  1. The LP relaxation, with its rows added as they are violated and its variables as they
//     price in: starting from the variables of a greedy selection and no row, each round
//     adds the most violated rows (none sharing a positive variable with a row added before
//     it in that round) or, when no row is violated, the variables with the largest positive
//     reduced costs under the duals of the rows, and lp_solve solves again from its last
//     basis, until neither is left. The relaxation's optimum is that of the full LP, but
//     lp_solve works on part of it (bench/RESULTS.md has the dragon's figures).
//  2. Relax and fix: variables at 1 in the relaxation are taken, those at 0 left out, and the
//     fractional rest, which splits into small independent parts, is solved exactly part by
//     part by branch and bound; any variable left free after that is added, heaviest first.
//  3. If that selection is not within the relative gap of the relaxation's optimum, branch
//     and bound runs on the whole program with every row, from the relaxation's basis,
//     accepting only selections better than step 2's, until it proves there is none, its
//     best has not improved for the stall limit (branch-and-bound nodes, counted from step
//     2's selection) or the time runs out (a safety stop). The better selection is kept.
#pragma once

#include "solver/integer_program.h"

#include <string>
#include <vector>

namespace fcql {

struct SetPackingOptions {
  double relativeGap = 1e-3;      ///< a selection this close to the best bound is optimal enough
  long stallNodes = 0;            ///< branch and bound stops after this many nodes without a better selection (0: never)
  double timeLimitSeconds = 60;   ///< for all three steps together (at least one second each): a safety stop
};

struct SetPackingResult {
  IntegerProgram::Status status = IntegerProgram::Status::Failed;
  std::vector<char> chosen;       ///< per variable
  double objective = 0;
  double bound = 0;               ///< the LP relaxation's optimum: no selection is better
  std::string message;            ///< how it was solved, or why it failed
  int relaxationRounds = 0;       ///< LP solves in step 1
  int rowsInRelaxation = 0;       ///< rows step 1 needed
  int columnsInRelaxation = 0;    ///< variables step 1 needed
  int fractional = 0;             ///< variables with a fractional value in the relaxation
  int fractionalParts = 0;        ///< independent parts among them (step 2)
  bool branchAndBound = false;    ///< step 3 ran
  bool warmStarted = false;       ///< step 3 started from the relaxation's basis
  bool improvedByBranchAndBound = false;
  bool timeLimitReached = false;  ///< the safety time limit cut some step short (the result depends on the machine)
  bool hasSolution() const {
    return status == IntegerProgram::Status::Optimal || status == IntegerProgram::Status::TimeLimit ||
           status == IntegerProgram::Status::Stalled || status == IntegerProgram::Status::WorkLimit;
  }
};

/// The greedy selection: heaviest first (ties: lower index first), each variable taken if no
/// row it is in holds a taken one already. Same input rules as solveSetPacking.
std::vector<char> greedyPacking(const std::vector<double>& weight, const std::vector<std::vector<int>>& rows);

/// `rows`: sets of variable indices in [0, weight.size()), each without repeats (a row of one
/// variable or none constrains nothing); weights positive and finite. Throws
/// std::invalid_argument otherwise. Once the time limit is spent, the fractional parts and
/// step 3 are skipped (status TimeLimit).
SetPackingResult solveSetPacking(const std::vector<double>& weight, const std::vector<std::vector<int>>& rows,
                                 const SetPackingOptions& options);

}  // namespace fcql
