// The relaxed 0-1 program of the paper (§4.1): choose candidate separatrices so that each
// port has at most one (Eq. 2, Consistency), no two chosen ones cross tangentially (Eq. 3,
// Orthogonality), maximising Σ c_i / γ(s_i) (Eq. 4).
#pragma once

#include "solver/integer_program.h"
#include "tracing/separatrix_graph.h"

#include <string>
#include <vector>

namespace fcql {

struct SelectionResult {
  std::vector<int> selected;  ///< indices into the SeparatrixGraph's arcs, increasing
  IntegerProgram::Status status = IntegerProgram::Status::Optimal;
  std::string message;        ///< lp_solve's word when not simply optimal
  double seconds = 0;
  int variables = 0;   ///< one per candidate both of whose ports are free
  int dominated = 0;   ///< variables left out because another one dominates them
  int constraints = 0; ///< rows of the program lp_solve gets (after leaving those out)
  int stalledParts = 0; ///< parts whose branch and bound stopped at the stall limit
  int timeLimitedParts = 0; ///< parts the safety time limit cut short (the selection then depends on the machine)
};

/// `portFree[p]` = 1 if port p may receive a separatrix (empty: all ports). Arcs touching a
/// port that is not free are left out. Throws std::runtime_error with lp_solve's reason if no
/// solution could be found (the empty selection is always feasible, so this means a solver
/// failure). Its conflict rows are graph H's tangential cliques. Branch and bound on each part stops once `stallNodes` nodes
/// brought no better solution (0: never), which gives the same selection on any machine; all
/// parts together stop within `timeLimitSeconds` (a safety stop, counted in timeLimitedParts).
SelectionResult selectSeparatrices(const SeparatrixGraph& h, const std::vector<char>& portFree, double timeLimitSeconds,
                                   long stallNodes = 0);

/// Which arcs a selection may use and how it weighs them.
struct SelectionScope {
  std::vector<char> portFree;    ///< as above (empty: all ports)
  std::vector<char> arcAllowed;  ///< per arc of H, 1 if it may be selected (empty: all)
  /// Each arc weighs 1 + ε · (longest length − its length), with ε so small that the length
  /// part of any selection is below half an arc: covering more ports comes first, then the
  /// shortest in all (the paper's Completeness made worth more than any length saving).
  bool coverageFirst = false;
};
SelectionResult selectSeparatricesIn(const SeparatrixGraph& h, const SelectionScope& scope, double timeLimitSeconds,
                                   long stallNodes = 0);

}  // namespace fcql
