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

}  // namespace

SelectionResult selectSeparatrices(const SeparatrixGraph& h, const std::vector<char>& portFree, double timeLimitSeconds,
                                   long stallNodes) {
  SelectionResult out;
  const auto start = std::chrono::steady_clock::now();  // the program's construction counts too
  auto free = [&](int p) { return portFree.empty() || (p >= 0 && p < int(portFree.size()) && portFree[p]); };
  // Scale the objective so that coefficients are near 1 whatever the mesh units.
  double meanLength = 0;
  for (const auto& a : h.arcs) meanLength += a.length;
  meanLength = h.arcs.empty() ? 1 : meanLength / h.arcs.size();
  std::vector<int> variableOf(h.arcs.size(), -1);
  std::vector<int> arcOf;
  std::vector<double> weight;
  for (int i = 0; i < int(h.arcs.size()); ++i) {
    const auto& a = h.arcs[i];
    if (!free(a.portA) || !free(a.portB) || !(a.length > 0)) continue;
    variableOf[i] = int(arcOf.size());
    arcOf.push_back(i);
    weight.push_back(meanLength / a.length);
  }
  const int n = int(arcOf.size());
  // Constraints, each "at most one of these": Eq. 2 per port, Eq. 3 as conflict cliques per
  // triangle (every tangential pair meets in some triangle, so the cliques cover them all).
  std::vector<std::vector<int>> rows;
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
  out.variables = n;
  // Variables another one dominates are left out (exact: an optimal solution remains).
  const std::vector<char> leftOut = removeDominatedVariables(rows, weight).fixedToZero;
  out.dominated = int(std::count(leftOut.begin(), leftOut.end(), 1));
  if (out.dominated > 0) {
    for (auto& row : rows) row.erase(std::remove_if(row.begin(), row.end(), [&](int v) { return leftOut[v]; }), row.end());
    rows.erase(std::remove_if(rows.begin(), rows.end(), [](const std::vector<int>& row) { return row.size() < 2; }),
               rows.end());
    rows = withoutContainedRows(rows, n);
  }
  out.constraints = int(rows.size());

  // The program splits into independent parts (connected through shared constraints).
  UnionFind uf(n);
  for (const auto& row : rows)
    for (std::size_t i = 1; i < row.size(); ++i) uf.unite(row[0], row[i]);
  std::vector<std::vector<int>> members(n), rowsOf(n);
  for (int v = 0; v < n; ++v)
    if (!leftOut[v]) members[uf.find(v)].push_back(v);
  for (int r = 0; r < int(rows.size()); ++r) rowsOf[uf.find(rows[r][0])].push_back(r);

  std::vector<char> chosen(n, 0);
  int usedGreedy = 0, parts = 0, programs = 0, timedOut = 0, stalled = 0;
  double worstGap = 0;  // of the parts not proven optimal: how far below their LP bound
  std::vector<int> local(n, -1);  // a variable's index in its part
  std::vector<double> localWeight;
  std::vector<std::vector<int>> localRows;

  for (int root = 0; root < n; ++root) {
    const auto& vars = members[root];
    if (vars.empty()) continue;
    ++parts;
    if (vars.size() == 1) {  // unconstrained: take it
      chosen[vars[0]] = 1;
      continue;
    }
    localWeight.clear();
    for (int v : vars) local[v] = int(localWeight.size()), localWeight.push_back(weight[v]);
    localRows.clear();
    for (int r : rowsOf[root]) {
      localRows.emplace_back();
      for (int v : rows[r]) localRows.back().push_back(local[v]);
    }
    // Greedy (best ratio first) is the fallback when lp_solve cannot do better in time.
    const std::vector<char> greedy = greedyPacking(localWeight, localRows);
    double greedyObjective = 0;
    for (std::size_t i = 0; i < greedy.size(); ++i) greedyObjective += greedy[i] ? localWeight[i] : 0;
    const double secondsLeft =
        timeLimitSeconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (secondsLeft <= 0) {  // the time is spent: the greedy selection for the parts left
      ++timedOut, ++usedGreedy;
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
    ++programs;
    if (r.timeLimitReached || !r.hasSolution()) ++timedOut;
    if (r.status == IntegerProgram::Status::Stalled) ++stalled;
    if (r.hasSolution() && r.status != IntegerProgram::Status::Optimal)
      worstGap = std::max(worstGap, (r.bound - r.objective) / std::max(1.0, std::abs(r.bound)));
    if (!r.hasSolution() || r.objective < greedyObjective - 1e-9) {
      ++usedGreedy;
      for (int v : vars) chosen[v] = greedy[local[v]];
    } else {
      for (int v : vars) chosen[v] = r.chosen[local[v]];
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
    out.message = "lp_solve had " + num(programs) + " of " + num(parts) +
                  " independent parts to solve; safety time limit reached (or no solution found): " + num(timedOut) +
                  stall +
                  "; " +
                  (usedGreedy ? "the greedy selection was better on " + num(usedGreedy)
                              : std::string("the best solutions found are kept"));
    if (worstGap > 0) {
      char gap[64];
      std::snprintf(gap, sizeof gap, " (at most %.2g%% below their LP bound)", 100 * worstGap);
      out.message += gap;
    }
  }
  for (int v = 0; v < n; ++v)
    if (chosen[v]) out.selected.push_back(arcOf[v]);
  std::sort(out.selected.begin(), out.selected.end());
  return out;
}

}  // namespace fcql
