// The solving cycle of the paper (§4.2) and the propagation of dangling ports into
// t-junctions and border connections (§4.2 end, §4.3).
//
// 1. Select separatrices from the candidates H with the relaxed 0-1 program.
// 1b. Coverage repair (coverage_repair.h): around each port the program left dangling, a
//    neighbourhood of H is selected again with covering ports first; kept where it covers more.
// 2. Solving cycle: freeze the selection as barriers, search again from the dangling ports
//    (sinks only at dangling ports), select among the new candidates, add; repeat until
//    nothing new is added.
// 2b. Completion (layout_completion.h): where ports are still dangling, the separatrices that
//    keep them apart are freed and the ports around them matched again, coverage first;
//    kept only where it leaves fewer t-junctions.
// 3. Propagation: from every port still dangling, trace until the first orthogonal crossing
//    with the layout (a t-junction), the border, or another dangling port. Paths are accepted
//    shortest first in rounds; a path that meets another path accepted in the same round is
//    traced again in the next round against the grown layout.
// 4. Dead ends: separatrices that would leave a slit inside a patch are removed
//    (removeDeadEnds).
#pragma once

#include "layout/coverage_repair.h"
#include "layout/separatrix_selection.h"
#include "tracing/separatrix_graph.h"

#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fcql {

/// How many of Layout::leftPorts the front ends log, one line each (the rest are counted).
constexpr std::size_t kLeftPortLines = 20;

/// Completion trials granted per defect on top of LayoutParameters::completionTrials: the dragon's
/// shipped field (795 singularities) leaves 326 defects after the solving cycle; its completion
/// kept 10 of 24 trials (302 left), 58 of 200 (200 left), 73 of 400 (170 left).
constexpr double kCompletionTrialsPerDefect = 1.25;

struct LayoutParameters {
  /// Seconds per 0-1 program (≥ 1): a safety stop only. Where it is reached the selection
  /// depends on the machine's speed, and the log and Layout::ilpTimeLimitHit say so.
  double ilpTimeLimit = 60;
  /// Branch and bound stops once this many of its nodes brought no better solution (0: only
  /// the time limit stops it). Counted in nodes, not seconds, so that the same input gives the
  /// same layout on any machine. See IntegerProgram::setStallNodes and solveSetPacking: on
  /// the selection it starts from the relaxation fixed by parts, within 1% of the LP bound
  /// (bench/RESULTS.md has the measurements on the shared meshes).
  long ilpStallNodes = 50;
  int maxIterations = 20;    ///< bound on the solving cycle
  /// Step 2b tries at most this many sets of separatrices to free, plus kCompletionTrialsPerDefect
  /// per t-junction (or unresolved port) the layout has when it starts (each trial a solving
  /// cycle on the ports it frees, and a propagation to count the t-junctions if fewer ports are
  /// left dangling): a bound in work, not time. 0 leaves step 2b out.
  int completionTrials = 24;
  bool coverageRepair = true;  ///< step 1b (off: the first program's selection as Eq. 4 leaves it)
  bool propagate = true;     ///< step 3

  /// Throws std::invalid_argument naming the parameter.
  void validate() const;
};

struct LayoutSeparatrix {
  enum Kind { Full, TJunction, Border };
  Kind kind = Full;
  int portA = -1, portB = -1;  ///< portB is −1 for t-junction and border paths
  int iteration = 0;           ///< 1 = first program, 2.. = solving cycle, 0 = propagation
  TracedPath path;
};

/// What step 2b did.
struct CompletionReport {
  int tJunctionsBefore = 0;  ///< t-junctions and unresolved ports propagation would leave before it
  int tJunctionsAfter = 0;   ///< ... and after it
  int trials = 0;            ///< sets of separatrices freed and matched again
  int accepted = 0;          ///< trials kept (each left fewer t-junctions)
  int freedSeparatrices = 0; ///< separatrices replaced in the trials kept
  /// For the ports still dangling when it last looked: why no separatrix joins them.
  std::map<int, std::string> reasons;
  /// The dangling ports with options (sets of separatrices to free) left untried when the
  /// trials ran out: the only ones a larger --completion-trials could still join.
  std::set<int> untriedPorts;
};

struct Layout {
  std::vector<LayoutSeparatrix> separatrices;
  int iterations = 0;             ///< 0-1 programs solved (first + cycle)
  int selectedFromCandidates = 0; ///< separatrices chosen in the first program
  int danglingAfterCycle = 0;     ///< ports without a separatrix after the solving cycle and the completion
  int tJunctions = 0;
  int borderConnections = 0;
  std::vector<int> unresolvedPorts;  ///< dangling ports no propagation could resolve
  /// On a surface with a border: the ports propagation ended at a t-junction after a search
  /// from them, crossing the layout orthogonally, reached neither the border nor a dangling port.
  std::set<int> borderOutOfReach;
  /// Per t-junction or unresolved port: port, singularity vertex and why it was left.
  std::vector<std::string> leftPorts;
  int deadEndsRemoved = 0;        ///< separatrices dropped by removeDeadEnds
  bool ilpTimeLimitHit = false;
  int ilpStalled = 0;             ///< parts of 0-1 programs stopped at the stall limit
  int ilpTimeLimited = 0;         ///< parts the safety time limit cut short
  std::vector<std::string> messages; ///< solver notes worth logging
  CoverageRepairReport coverageRepair;  ///< step 1b
  CompletionReport completion;
  double ilpSeconds = 0, cycleTracingSeconds = 0, propagationSeconds = 0, completionSeconds = 0;
};

Layout solveLayout(const GeodesicGraph& graph, const SeparatrixGraph& candidates, const LayoutParameters& params);

// The steps of solveLayout, for the completion step and tests.

/// How the solving cycle weighs its candidates: Eq. 4 (Length), or so that covering one port
/// more outweighs any saving in length, the shortest in all among equal covers (CoverageFirst:
/// SelectionScope::coverageFirst).
enum class SelectionWeights { Length, CoverageFirst };
/// Step 2: searches from the dangling ports with `layout` frozen as barriers, selection among
/// the new candidates, until nothing is added (at most params.maxIterations − 1 rounds). With
/// `sourcesOnly`, only the dangling ports it marks are searched from (every free port is a sink).
/// Each search stops after `maxSinks` sinks (0: k, the graph's parameter) and seeks no path
/// longer than `maxLength`.
void runSolvingCycle(const GeodesicGraph& graph, Layout& layout, const LayoutParameters& params,
                     SelectionWeights weights, const std::vector<char>* sourcesOnly = nullptr, int maxSinks = 0,
                     double maxLength = std::numeric_limits<double>::infinity());
/// Step 3 without the dead-end removal: every dangling port traced to a t-junction, the
/// border or another dangling port; ports that reach nothing join unresolvedPorts.
void propagateDanglingPorts(const GeodesicGraph& graph, Layout& layout);
/// The layout's separatrices as barriers, each with its index in layout.separatrices as id.
BarrierSet layoutBarriers(const GeodesicGraph& graph, const Layout& layout);

/// Removes the separatrices that end at an interior singular vertex reached by no other
/// separatrix (its other ports unresolved, or a singularity of index 3/4, which has a single
/// port): each would run into a patch and stop there, a slit that no grid of quads fits. The
/// singularity then lies inside a patch. Removal cascades to t-junction paths that ended on a
/// removed separatrix and to singularities left with a single separatrix. Returns how many
/// were removed; t-junction and border counts are updated and the removed separatrices' ports
/// join unresolvedPorts. Called by solveLayout (step 4).
int removeDeadEnds(const GeodesicGraph& graph, Layout& layout);

/// Ports that have a separatrix in `layout` (per port, 1 = used).
std::vector<char> usedPorts(const GeodesicGraph& graph, const Layout& layout);
/// Ports that have no separatrix in `layout` (the dangling ones), increasing.
std::vector<int> danglingPorts(const GeodesicGraph& graph, const Layout& layout);

/// What the solving cycle's searches have shown out of reach. A search that found fewer sinks
/// than it wanted ran out of graph, so every sink it was allowed and did not find is out of
/// reach of its port; with barriers that only grow from round to round, it stays so. Used by
/// solveLayout (step 2) to leave those sinks out of the port's later searches.
class SinksOutOfReach {
public:
  explicit SinksOutOfReach(int numPorts) : far_(numPorts) {}
  /// The sinks a search from `port` may stop at: the `free` ports but itself and those out of
  /// its reach.
  std::vector<char> allowedFrom(int port, const std::vector<char>& free) const;
  /// Takes note of a search from `port` that was allowed the sinks `allowed`, could stop after
  /// `maxSinks` of them (k) and found the paths `found`.
  void note(int port, const std::vector<char>& allowed, int maxSinks, const std::vector<TracedPath>& found);
  bool outOfReach(int port, int sink) const { return !far_[port].empty() && far_[port][sink]; }

private:
  std::vector<std::vector<char>> far_;  ///< per port, per sink (empty: none known)
};

}  // namespace fcql
