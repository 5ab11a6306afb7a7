// Integer side lengths for the patches (§4.4): one integer n_s ≥ 1 per segment, as close as
// possible (L1) to its ideal subdivision length(s) / targetEdgeLength, with the opposite
// sides of every patch equal: exactly where neither side carries a t-junction, in an L1
// sense (heavily weighted) where one does. Segments forced equal (single-segment opposite
// sides) share one count (a chord class); the program then splits into independent parts,
// classes linked by the remaining equalities: a class in none takes its best rounding
// directly, each other part is solved with lp_solve on its own (branch and bound, or, where
// that finds no solution within the time limit, its LP relaxation rounded).
#pragma once

#include "solver/integer_program.h"
#include "quadrangulation/patch_sides.h"

#include <string>
#include <vector>

namespace fcql {

struct SideLengths {
  std::vector<int> segments;          ///< n_s per segment
  std::vector<int> inconsistentPatches;  ///< patches whose opposite sides still differ (zero chains)
  IntegerProgram::Status status = IntegerProgram::Status::Optimal;
  std::string message;
  double seconds = 0;
  int parts = 0;     ///< independent parts of the program
  int programs = 0;  ///< parts that needed lp_solve (the others are single classes)
  int roundedParts = 0;  ///< of those, parts solved by rounding the LP relaxation
  int timeLimitedParts = 0;  ///< parts the safety time limit cut short (the quads then depend on the machine)
  int budgetLimitedParts = 0;  ///< parts branch and bound left at its node budget (not proven optimal)

  /// Subdivisions along side k of patch p.
  int sideLength(const PatchGraph& g, int p, int k) const;
};

/// `timeLimitSeconds` bounds the whole; within what is left of it, branch and bound gets up
/// to 10 s for a part of at most 1000 variables (so that it finishes and the same input gives
/// the same counts on every run) and 2 s for a larger one, whose relaxation is then rounded
/// too (the better solution is kept). Throws std::runtime_error if lp_solve fails even on the
/// LP relaxation. Patches with forceEqual get hard equalities; if that makes the program
/// infeasible it is solved again without them. With `boundStretch`, no segment is sampled
/// more than 1.5 times coarser than the target (a lower bound on each count); without it
/// only counts of at least 1 are asked for, which the zero-chain splits can always satisfy.
/// With `previous` (a warm round after zero-chain splits: the last counts, per segment that
/// existed then), only the classes on patches that gained segments are solved again; the
/// others keep their counts, which enter those patches' equalities as constants.
SideLengths solveSideLengths(const PatchGraph& graph, double targetEdgeLength, double timeLimitSeconds,
                             bool boundStretch = true, const std::vector<int>* previous = nullptr);

}  // namespace fcql
