#include "layout/separatrix_selection.h"

#include "layout/independent_set_reduction.h"
#include "solver/set_packing.h"
#include "util/union_find.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fcql {
namespace {

/// Drops the rows contained in another row: every row says "at most one of these", so a
/// row inside a larger one adds nothing (cliques of neighbouring triangles often nest; on
/// fertility half of the rows). Rows are sorted sets of variables; the order of the kept ones
/// is unchanged.
std::vector<std::vector<int>> withoutContainedRows(const std::vector<std::vector<int>>& rows, int numVariables) {
  std::vector<int> order(rows.size());
  for (int r = 0; r < int(rows.size()); ++r) order[r] = r;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rows[a].size() > rows[b].size(); });
  std::vector<std::vector<int>> rowsWith(numVariables);  // kept rows holding each variable
  std::vector<char> keep(rows.size(), 0);
  for (int r : order) {
    const std::vector<int>& row = rows[r];
    int rarest = row[0];
    for (int v : row)
      if (rowsWith[v].size() < rowsWith[rarest].size()) rarest = v;
    bool contained = false;
    for (int k : rowsWith[rarest])
      if (k != r && std::includes(rows[k].begin(), rows[k].end(), row.begin(), row.end())) {
        contained = true;
        break;
      }
    if (contained) continue;
    keep[r] = 1;
    for (int v : row) rowsWith[v].push_back(r);
  }
  std::vector<std::vector<int>> kept;
  for (int r = 0; r < int(rows.size()); ++r)
    if (keep[r]) kept.push_back(rows[r]);
  return kept;
}

/// The 0-1 program of the selection: one variable per arc of H between free ports, rows
/// "at most one of these".
struct SelectionProgram {
  std::vector<int> arcOf;                ///< variable -> arc of H
  std::vector<double> weight;            ///< variable -> objective coefficient
  std::vector<std::vector<int>> rows;    ///< sorted sets of variables
  std::vector<char> leftOut;             ///< variable -> dominated, left out
  int numVariables() const { return int(arcOf.size()); }
};

/// Step 1: the variables (arcs between free ports, weighted by mean length / length) and the
/// rows: Eq. 2 per port, Eq. 3 as conflict cliques per triangle (every tangential pair meets
/// in some triangle, so the cliques cover them all), without the rows inside another.
SelectionProgram buildProgram(const SeparatrixGraph& h, const SelectionScope& scope) {
  SelectionProgram program;
  const std::vector<char>& portFree = scope.portFree;
  auto free = [&](int p) { return portFree.empty() || (p >= 0 && p < int(portFree.size()) && portFree[p]); };
  auto allowed = [&](int i) { return scope.arcAllowed.empty() || scope.arcAllowed.at(i) != 0; };
  // Scale the objective so that coefficients are near 1 whatever the mesh units.
  double meanLength = 0;
  for (const auto& a : h.arcs) meanLength += a.length;
  meanLength = h.arcs.empty() ? 1 : meanLength / h.arcs.size();
  std::vector<int> variableOf(h.arcs.size(), -1);
  std::vector<int>& arcOf = program.arcOf;
  for (int i = 0; i < int(h.arcs.size()); ++i) {
    const auto& a = h.arcs[i];
    if (!free(a.portA) || !free(a.portB) || !allowed(i) || !(a.length > 0)) continue;
    variableOf[i] = int(arcOf.size());
    arcOf.push_back(i);
    program.weight.push_back(meanLength / a.length);
  }
  if (scope.coverageFirst && !arcOf.empty()) {
    // Each arc weighs 1 + ε · (longest − its length): among selections of as many arcs, the
    // shortest in all wins. A selection holds at most one arc per two ports of its arcs, so its
    // length part stays below (ports / 2 + 1) · longest · ε, half an arc.
    std::vector<char> seen(h.arcsAtPort.size(), 0);
    int ports = 0;
    for (int i : arcOf)
      for (int p : {h.arcs[i].portA, h.arcs[i].portB})
        if (p >= 0 && p < int(seen.size()) && !seen[p]) seen[p] = 1, ++ports;
    double longest = 0;
    for (int i : arcOf) longest = std::max(longest, h.arcs[i].length);
    const double epsilon = 1.0 / (2.0 * (ports / 2 + 1) * longest);
    for (std::size_t v = 0; v < arcOf.size(); ++v) program.weight[v] = 1 + epsilon * (longest - h.arcs[arcOf[v]].length);
  }
  const int n = int(arcOf.size());
  std::vector<std::vector<int>>& rows = program.rows;
  for (int p = 0; p < int(h.arcsAtPort.size()); ++p) {
    std::vector<int> row;
    for (int a : h.arcsAtPort[p])
      if (variableOf[a] >= 0) row.push_back(variableOf[a]);
    std::sort(row.begin(), row.end());
    if (row.size() > 1) rows.push_back(std::move(row));
  }
  for (const auto& clique : h.tangentialCliques) {
    std::vector<int> row;  // increasing, as variables are numbered in the order of the arcs
    for (int a : clique)
      if (variableOf[a] >= 0) row.push_back(variableOf[a]);
    if (row.size() >= 2) rows.push_back(std::move(row));
  }
  rows = withoutContainedRows(rows, n);
  return program;
}

/// Step 2: variables another one dominates are left out (exact: an optimal solution
/// remains), and the rows they leave short or contained dropped. Returns how many.
int leaveOutDominated(SelectionProgram& program) {
  const int n = program.numVariables();
  std::vector<std::vector<int>>& rows = program.rows;
  program.leftOut = removeDominatedVariables(rows, program.weight).fixedToZero;
  const std::vector<char>& leftOut = program.leftOut;
  const int dominated = int(std::count(leftOut.begin(), leftOut.end(), 1));
  if (dominated > 0) {
    for (auto& row : rows) row.erase(std::remove_if(row.begin(), row.end(), [&](int v) { return leftOut[v]; }), row.end());
    rows.erase(std::remove_if(rows.begin(), rows.end(), [](const std::vector<int>& row) { return row.size() < 2; }),
               rows.end());
    rows = withoutContainedRows(rows, n);
  }
  return dominated;
}

/// The program's independent parts (connected through shared constraints), by root variable.
struct IndependentParts {
  std::vector<std::vector<int>> members;  ///< root -> its variables (not left out)
  std::vector<std::vector<int>> rowsOf;   ///< root -> its rows
};

IndependentParts independentParts(const SelectionProgram& program) {
  const int n = program.numVariables();
  UnionFind uf(n);
  for (const auto& row : program.rows)
    for (std::size_t i = 1; i < row.size(); ++i) uf.unite(row[0], row[i]);
  IndependentParts parts;
  parts.members.resize(n);
  parts.rowsOf.resize(n);
  for (int v = 0; v < n; ++v)
    if (!program.leftOut[v]) parts.members[uf.find(v)].push_back(v);
  for (int r = 0; r < int(program.rows.size()); ++r) parts.rowsOf[uf.find(program.rows[r][0])].push_back(r);
  return parts;
}

/// How the parts were solved.
struct PartsTally {
  int usedGreedy = 0, parts = 0, programs = 0, timedOut = 0, stalled = 0;
  double worstGap = 0;  ///< of the parts not proven optimal: how far below their LP bound
};

/// Step 3: each part solved as a set packing by lp_solve within the time left, or the greedy
/// selection where it is better or the time is spent; `chosen` per variable.
PartsTally solveParts(const SelectionProgram& program, const IndependentParts& partsByRoot,
                      std::chrono::steady_clock::time_point start, double timeLimitSeconds, long stallNodes,
                      std::vector<char>& chosen) {
  const int n = program.numVariables();
  PartsTally tally;
  chosen.assign(n, 0);
  std::vector<int> local(n, -1);  // a variable's index in its part
  std::vector<double> localWeight;
  std::vector<std::vector<int>> localRows;

  for (int root = 0; root < n; ++root) {
    const auto& vars = partsByRoot.members[root];
    if (vars.empty()) continue;
    ++tally.parts;
    if (vars.size() == 1) {  // unconstrained: take it
      chosen[vars[0]] = 1;
      continue;
    }
    localWeight.clear();
    for (int v : vars) local[v] = int(localWeight.size()), localWeight.push_back(program.weight[v]);
    localRows.clear();
    for (int r : partsByRoot.rowsOf[root]) {
      localRows.emplace_back();
      for (int v : program.rows[r]) localRows.back().push_back(local[v]);
    }
    // Greedy (best ratio first) is the fallback when lp_solve cannot do better in time.
    const std::vector<char> greedy = greedyPacking(localWeight, localRows);
    double greedyObjective = 0;
    for (std::size_t i = 0; i < greedy.size(); ++i) greedyObjective += greedy[i] ? localWeight[i] : 0;
    const double secondsLeft =
        timeLimitSeconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (secondsLeft <= 0) {  // the time is spent: the greedy selection for the parts left
      ++tally.timedOut, ++tally.usedGreedy;
      for (int v : vars) chosen[v] = greedy[local[v]];
      continue;
    }
    SetPackingOptions options;
    // Optimal up to rounding: selections within 0.1% of each other can give very different
    // layouts (kitten at φ 25°: 126 patches 0.025% below the optimum's 83), and where branch
    // and bound cannot settle a part the stall limit stops it.
    options.relativeGap = 1e-6;
    options.stallNodes = stallNodes;
    options.timeLimitSeconds = secondsLeft;
    const SetPackingResult r = solveSetPacking(localWeight, localRows, options);
    ++tally.programs;
    if (r.timeLimitReached || !r.hasSolution()) ++tally.timedOut;
    if (r.status == IntegerProgram::Status::Stalled) ++tally.stalled;
    if (r.hasSolution() && r.status != IntegerProgram::Status::Optimal)
      tally.worstGap = std::max(tally.worstGap, (r.bound - r.objective) / std::max(1.0, std::abs(r.bound)));
    if (!r.hasSolution() || r.objective < greedyObjective - 1e-9) {
      ++tally.usedGreedy;
      for (int v : vars) chosen[v] = greedy[local[v]];
    } else {
      for (int v : vars) chosen[v] = r.chosen[local[v]];
    }
  }
  return tally;
}

/// Step 4: the selection's status and, unless every part was solved to optimality, the
/// message that says how it was not.
void reportStatus(const PartsTally& tally, long stallNodes, SelectionResult& out) {
  const int stalled = tally.stalled, timedOut = tally.timedOut, usedGreedy = tally.usedGreedy;
  out.stalledParts = stalled;
  out.timeLimitedParts = timedOut;
  // The greedy selection can beat lp_solve's where lp_solve stopped early, or by less than the
  // 10⁻⁶ gap on a part it settled; the status says whether lp_solve stopped early.
  out.status = timedOut > 0 ? IntegerProgram::Status::TimeLimit
               : stalled > 0 ? IntegerProgram::Status::Stalled
                             : IntegerProgram::Status::Optimal;
  if (out.status != IntegerProgram::Status::Optimal) {
    auto num = [](int k) { return std::to_string(k); };
    std::string stall;
    if (stalled > 0)
      stall = ", stopped after " + std::to_string(stallNodes) + " nodes without a better solution: " + num(stalled);
    out.message = "lp_solve had " + num(tally.programs) + " of " + num(tally.parts) +
                  " independent parts to solve; safety time limit reached (or no solution found): " + num(timedOut) +
                  stall +
                  "; " +
                  (usedGreedy ? "the greedy selection was better on " + num(usedGreedy)
                              : std::string("the best solutions found are kept"));
    if (tally.worstGap > 0) {
      char gap[64];
      std::snprintf(gap, sizeof gap, " (at most %.2g%% below their LP bound)", 100 * tally.worstGap);
      out.message += gap;
    }
  }
}

}  // namespace

SelectionResult selectSeparatrices(const SeparatrixGraph& h, const std::vector<char>& portFree, double timeLimitSeconds,
                                   long stallNodes) {
  SelectionScope scope;
  scope.portFree = portFree;
  return selectSeparatricesIn(h, scope, timeLimitSeconds, stallNodes);
}

SelectionResult selectSeparatricesIn(const SeparatrixGraph& h, const SelectionScope& scope, double timeLimitSeconds,
                                   long stallNodes) {
  SelectionResult out;
  const auto start = std::chrono::steady_clock::now();  // the program's construction counts too
  SelectionProgram program = buildProgram(h, scope);
  out.variables = program.numVariables();
  out.dominated = leaveOutDominated(program);
  out.constraints = int(program.rows.size());
  const IndependentParts parts = independentParts(program);
  std::vector<char> chosen;
  const PartsTally tally = solveParts(program, parts, start, timeLimitSeconds, stallNodes, chosen);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  reportStatus(tally, stallNodes, out);
  for (int v = 0; v < program.numVariables(); ++v)
    if (chosen[v]) out.selected.push_back(program.arcOf[v]);
  std::sort(out.selected.begin(), out.selected.end());
  return out;
}

}  // namespace fcql
