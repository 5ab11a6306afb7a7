// IntegerProgram: a small, self-contained front end to lp_solve 5.5 for the two integer
// programs of the pipeline (separatrix selection, side lengths). Variables have bounds and may
// be integer or binary; constraints are sparse rows with ≤, ≥ or =. lp_solve always runs with
// a time limit; when it is hit the best feasible solution found so far is returned, flagged.
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
    Stalled,      ///< the best solution stopped improving (setStallLimit); `values` holds it
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
    bool hasSolution() const {
      return status == Status::Optimal || status == Status::TimeLimit || status == Status::Stalled;
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
  /// Branch and bound stops once it has a solution and has not improved it for this many
  /// seconds (0: never; only the time limit stops it). On large programs lp_solve finds its
  /// best solution soon after the LP relaxation and then spends the rest of the limit on
  /// nodes that barely improve it (the dragon's first 0-1 program: best found at 6 s; the
  /// 54 s left of its limit added 0.002% to the objective).
  void setStallLimit(double seconds) { stallSeconds_ = seconds; }

  int numVariables() const { return int(lower_.size()); }
  int numConstraints() const { return int(rows_.size()); }

  /// Solves with lp_solve. `timeLimitSeconds` ≥ 1 (lp_solve's resolution is one second).
  Result solve(double timeLimitSeconds) const;
  /// A feasible solution without branch and bound, for programs lp_solve cannot settle in
  /// time: the LP relaxation is solved, its integer variables with integral values are fixed
  /// there and the others rounded, nearest to an integer first and at most one of them per
  /// constraint at a time, and so on until every integer variable is fixed. Status TimeLimit
  /// (feasible, not proven optimal), or Optimal if the first relaxation is integral already.
  /// Rounding can make equality constraints unsatisfiable: status Infeasible then, as for a
  /// program with no solution at all. Each LP solve may take the time limit or 60 s, whichever
  /// is longer (a relaxation cut short leaves nothing to round); once the limit is spent, all
  /// that is left is rounded at once and one more solve finishes.
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
  double stallSeconds_ = 0;
};

const char* toString(IntegerProgram::Status status);

}  // namespace fcql
