// IntegerProgram: a small, self-contained front end to lp_solve 5.5 for the two integer
// programs of the pipeline (separatrix selection, side lengths). Variables have bounds and may
// be integer or binary; constraints are sparse rows with ≤, ≥ or =. lp_solve always runs with
// node budgets (the same result on any machine) and a time limit as a safety stop; when either
// stops it, the best feasible solution found so far is returned, flagged.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

struct _lprec;

namespace fcql {

class IntegerProgram {
public:
  enum class Sense { LessEqual, GreaterEqual, Equal };
  enum class Status {
    Optimal,      ///< proven optimal
    TimeLimit,    ///< time limit hit; `values` holds the best feasible solution found
    Stalled,      ///< the best solution stopped improving (setStallNodes); `values` holds it
    WorkLimit,    ///< the node budget ran out (setNodeLimit); `values` holds the best solution found
    Infeasible,   ///< no solution satisfies the constraints
    Unbounded,
    Failed        ///< lp_solve failed (message says why), or time limit with no solution
  };
  struct Result {
    Status status = Status::Failed;
    std::vector<double> values;
    double objective = 0;
    double seconds = 0;
    std::string message;
    long nodes = 0;                 ///< branch-and-bound nodes lp_solve explored (solve)
    bool timeLimitReached = false;  ///< the safety time limit stopped it: the result depends on the machine's speed
    bool hasSolution() const {
      return status == Status::Optimal || status == Status::TimeLimit || status == Status::Stalled ||
             status == Status::WorkLimit;
    }
  };

  /// Adds a variable with bounds [lower, upper]; returns its index.
  int addVariable(double lower, double upper, bool integer, double objective = 0);
  int addBinary(double objective = 0) { return addVariable(0, 1, true, objective); }
  void setObjective(int variable, double coefficient);
  void addConstraint(const std::vector<std::pair<int, double>>& terms, Sense sense, double rhs);
  void setMaximize(bool maximize) { maximize_ = maximize; }
  /// Branch and bound stops when the best bound is within this relative gap of the best
  /// solution found (lp_solve's default is 1e-9).
  void setRelativeGap(double gap) { relativeGap_ = gap; }
  /// Branch and bound stops once it has a solution and this many nodes brought no better one
  /// (0: never). Counted in nodes, not seconds, so that the same program gives the same result
  /// on any machine. On large programs lp_solve finds its best solution soon after the LP
  /// relaxation and then spends long on nodes that barely improve it.
  void setStallNodes(long nodes) { stallNodes_ = nodes; }
  /// Branch and bound tries the lower branch (x ≤ ⌊x*⌋) of a fractional variable first
  /// instead of lp_solve's default upper one (its BRANCH_CEILING).
  void setBranchDownFirst(bool down) { branchDownFirst_ = down; }
  /// Branch and bound stops after this many nodes in all (0: no limit), keeping the best
  /// solution found (status WorkLimit).
  void setNodeLimit(long nodes) { nodeLimit_ = nodes; }
  int numVariables() const { return int(lower_.size()); }
  int numConstraints() const { return int(rows_.size()); }

  /// Solves with lp_solve. `timeLimitSeconds` ≥ 1 (lp_solve's resolution is one second) is a
  /// safety stop; the node limits above decide where a long branch and bound stops.
  Result solve(double timeLimitSeconds) const;
  /// A feasible solution without branch and bound, for programs lp_solve cannot settle in
  /// time: the LP relaxation is solved, its integer variables with integral values are fixed
  /// there and the others rounded, nearest to an integer first and at most one of them per
  /// constraint at a time, and so on until every integer variable is fixed. Status TimeLimit
  /// (feasible, not proven optimal), or Optimal if the first relaxation is integral already.
  /// Rounding can make equality constraints unsatisfiable: status Infeasible then, as for a
  /// program with no solution at all. After 50 rounds, all that is left is rounded at once and
  /// one more solve finishes. Each LP solve may take the time limit or 60 s, whichever is
  /// longer (a relaxation cut short leaves nothing to round); once the limit is spent, the
  /// rest is rounded at once too (a safety stop, flagged timeLimitReached).
  Result solveByRounding(double timeLimitSeconds) const;

private:
  std::unique_ptr<_lprec, void (*)(_lprec*)> buildModel(bool relaxed, std::string& message) const;

  struct Row {
    std::vector<std::pair<int, double>> terms;
    Sense sense;
    double rhs;
  };
  std::vector<double> lower_, upper_, objective_;
  std::vector<char> integer_;
  std::vector<Row> rows_;
  bool maximize_ = false;
  double relativeGap_ = 1e-9;
  long stallNodes_ = 0;
  bool branchDownFirst_ = false;
  long nodeLimit_ = 0;
};

const char* toString(IntegerProgram::Status status);

}  // namespace fcql
