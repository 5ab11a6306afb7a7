#include "layout/separatrix_selection.h"

#include "layout/independent_set_reduction.h"
#include "layout/set_packing.h"
#include "mesh/union_find.h"
#include "mesh/worker_threads.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace fcql {
namespace {

/// A piece of a candidate inside one triangle, as a variable of the program.
struct Piece {
  int variable;
  const PathSegment* segment;
};

using Cliques = std::set<std::vector<int>>;

/// A chord of a triangle and the variables whose pieces run along it: paths through a face
/// near a singularity mostly share a few chords (on fertility 51M pairs of pieces, 260K pairs
/// of distinct chords), and pieces on one chord meet exactly what the chord meets.
struct ChordGroup {
  double from, to;
  std::vector<int> variables;
};

/// Working memory of addTriangleCliques, reused from triangle to triangle.
struct CliqueScratch {
  std::vector<ChordGroup> chords;
  std::vector<char> meets, covered;  // m × m over the chords
  std::vector<int> members, vars;
};

/// Adds the conflict cliques of one triangle's pieces: pieces of the same direction parity
/// that pairwise meet can hold at most one selected separatrix. A greedy cover of the meeting
/// chords: each pair that meets and is not covered yet grows into a clique of all chords
/// meeting its members, and the clique holds every variable on those chords. A chord that
/// meets no other one still makes a clique of the variables along it.
void addTriangleCliques(const std::vector<Piece>& pieces, CliqueScratch& w, Cliques& cliques) {
  for (int parity = 0; parity < 2; ++parity) {
    w.chords.clear();
    for (const auto& p : pieces) {
      if (p.segment->direction % 2 != parity) continue;
      const double a = std::min(p.segment->from, p.segment->to), b = std::max(p.segment->from, p.segment->to);
      auto it = std::find_if(w.chords.begin(), w.chords.end(), [&](const ChordGroup& c) { return c.from == a && c.to == b; });
      if (it == w.chords.end()) it = w.chords.insert(w.chords.end(), ChordGroup{a, b, {}});
      if (std::find(it->variables.begin(), it->variables.end(), p.variable) == it->variables.end())
        it->variables.push_back(p.variable);
    }
    const int m = int(w.chords.size());
    if (m == 0) continue;
    w.meets.assign(std::size_t(m) * m, 0);
    w.covered.assign(std::size_t(m) * m, 0);
    auto at = [m](std::vector<char>& x, int i, int j) -> char& { return x[std::size_t(i) * m + j]; };
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        at(w.meets, i, j) = at(w.meets, j, i) =
            relateChords(w.chords[i].from, w.chords[i].to, w.chords[j].from, w.chords[j].to) != ChordRelation::Disjoint;
    auto emit = [&]() {
      w.vars.clear();
      for (int c : w.members) w.vars.insert(w.vars.end(), w.chords[c].variables.begin(), w.chords[c].variables.end());
      std::sort(w.vars.begin(), w.vars.end());
      w.vars.erase(std::unique(w.vars.begin(), w.vars.end()), w.vars.end());
      if (w.vars.size() >= 2) cliques.insert(w.vars);
    };
    for (int i = 0; i < m; ++i) {
      bool alone = true;
      for (int j = 0; j < m && alone; ++j) alone = j == i || !at(w.meets, i, j);
      if (alone) {
        w.members = {i};
        emit();
        continue;
      }
      for (int j = i + 1; j < m; ++j) {
        if (!at(w.meets, i, j) || at(w.covered, i, j)) continue;
        w.members = {i, j};
        for (int k = 0; k < m; ++k) {
          if (k == i || k == j) continue;
          bool all = true;
          for (int c : w.members) all = all && at(w.meets, k, c);
          if (all) w.members.push_back(k);
        }
        for (int a : w.members)
          for (int b : w.members) at(w.covered, a, b) = 1;
        emit();
      }
    }
  }
}

/// Conflict cliques of every triangle. Together they imply every pairwise Eq. 3 and make the
/// LP relaxation much tighter than the pairs alone. Triangles are shared out in blocks among
/// the threads, each with its own set: the union does not depend on who found what.
Cliques conflictCliques(const SeparatrixGraph& h, const std::vector<int>& variableOf, int requestedThreads) {
  int maxFace = -1;
  for (const auto& a : h.arcs)
    for (const auto& s : a.path.segments) maxFace = std::max(maxFace, s.face);
  std::vector<std::vector<Piece>> perFace(maxFace + 1);
  for (int i = 0; i < int(h.arcs.size()); ++i) {
    if (variableOf[i] < 0) continue;
    for (const auto& s : h.arcs[i].path.segments)
      if (s.face >= 0) perFace[s.face].push_back({variableOf[i], &s});
  }
  const int numFaces = int(perFace.size());
  const int blockSize = 256;
  const int numBlocks = (numFaces + blockSize - 1) / blockSize;
  const int threads = workerThreadCount(requestedThreads, numBlocks);
  std::vector<Cliques> found(threads);
  std::atomic<int> nextBlock{0};
  auto work = [&](int thread) {
    CliqueScratch scratch;
    for (int block; (block = nextBlock.fetch_add(1)) < numBlocks;)
      for (int f = block * blockSize, end = std::min(numFaces, f + blockSize); f < end; ++f)
        if (perFace[f].size() >= 2) addTriangleCliques(perFace[f], scratch, found[thread]);
  };
  runOnWorkerThreads(threads, work);
  Cliques cliques;
  for (Cliques& c : found) cliques.merge(c);
  return cliques;
}

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
                                   int threads, double stallSeconds) {
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
  std::vector<std::vector<int>> portsOfVariable(n);
  for (int p = 0; p < int(h.arcsAtPort.size()); ++p) {
    std::vector<int> row;
    for (int a : h.arcsAtPort[p])
      if (variableOf[a] >= 0) row.push_back(variableOf[a]), portsOfVariable[variableOf[a]].push_back(p);
    std::sort(row.begin(), row.end());
    if (row.size() > 1) rows.push_back(std::move(row));
  }
  for (const auto& clique : conflictCliques(h, variableOf, threads)) rows.push_back(clique);
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

  // Greedy (best ratio first) is the fallback when lp_solve cannot do better in time.
  std::vector<std::vector<int>> conflicts(n);
  for (const auto& pr : h.tangentialPairs) {
    int a = variableOf[pr.first], b = variableOf[pr.second];
    if (a >= 0 && b >= 0) conflicts[a].push_back(b), conflicts[b].push_back(a);
  }
  std::vector<char> chosen(n, 0);
  std::vector<char> portTaken(h.arcsAtPort.size(), 0);
  auto greedy = [&](const std::vector<int>& vars, std::vector<char>& taken) {
    std::vector<int> order = vars;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weight[a] > weight[b]; });
    double objective = 0;
    for (int v : order) {
      bool ok = true;
      for (int p : portsOfVariable[v]) ok = ok && !portTaken[p];
      for (int w : conflicts[v]) ok = ok && !taken[w];
      if (!ok) continue;
      taken[v] = 1;
      for (int p : portsOfVariable[v]) portTaken[p] = 1;
      objective += weight[v];
    }
    return objective;
  };

  int usedGreedy = 0, parts = 0, programs = 0, timedOut = 0, stalled = 0;
  double worstGap = 0;  // of the parts not proven optimal: how far below their LP bound

  for (int root = 0; root < n; ++root) {
    const auto& vars = members[root];
    if (vars.empty()) continue;
    ++parts;
    if (vars.size() == 1) {  // unconstrained: take it
      chosen[vars[0]] = 1;
      continue;
    }
    std::vector<char> greedyTaken(n, 0);
    double greedyObjective = greedy(vars, greedyTaken);
    std::vector<int> local(n, -1);
    std::vector<double> localWeight;
    for (int v : vars) local[v] = int(localWeight.size()), localWeight.push_back(weight[v]);
    std::vector<std::vector<int>> localRows;
    for (int r : rowsOf[root]) {
      localRows.emplace_back();
      for (int v : rows[r]) localRows.back().push_back(local[v]);
    }
    SetPackingOptions options;
    // Optimal up to rounding: selections within 0.1% of each other can give very different
    // layouts (kitten at φ 25°: 126 patches 0.025% below the optimum's 83), and where branch
    // and bound cannot settle a part the stall limit stops it.
    options.relativeGap = 1e-6;
    options.stallSeconds = stallSeconds;
    options.timeLimitSeconds =
        std::max(1.0, timeLimitSeconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const SetPackingResult r = solveSetPacking(localWeight, localRows, options);
    ++programs;
    if (r.status == IntegerProgram::Status::TimeLimit || !r.hasSolution()) ++timedOut;
    if (r.status == IntegerProgram::Status::Stalled) ++stalled;
    if (r.hasSolution() && r.status != IntegerProgram::Status::Optimal)
      worstGap = std::max(worstGap, (r.bound - r.objective) / std::max(1.0, std::abs(r.bound)));
    if (!r.hasSolution() || r.objective < greedyObjective - 1e-9) {
      ++usedGreedy;
      for (int v : vars) chosen[v] = greedyTaken[v];
    } else {
      for (int v : vars) chosen[v] = r.chosen[local[v]];
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.stalledParts = stalled;
  // The greedy selection can beat lp_solve's where lp_solve stopped early, or by less than the
  // 10⁻⁶ gap on a part it settled; the status says whether lp_solve stopped early.
  out.status = timedOut > 0 ? IntegerProgram::Status::TimeLimit
               : stalled > 0 ? IntegerProgram::Status::Stalled
                             : IntegerProgram::Status::Optimal;
  if (out.status != IntegerProgram::Status::Optimal) {
    auto num = [](int k) { return std::to_string(k); };
    std::string stall;
    if (stalled > 0) {
      char s[32];
      std::snprintf(s, sizeof s, "%g", stallSeconds);
      stall = ", stopped after " + std::string(s) + " s without a better solution: " + num(stalled);
    }
    out.message = "lp_solve had " + num(programs) + " of " + num(parts) +
                  " independent parts to solve; time limit reached (or no solution found): " + num(timedOut) + stall +
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
