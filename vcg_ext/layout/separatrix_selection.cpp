#include "layout/separatrix_selection.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>

namespace fcql {
namespace {

/// Conflict cliques: within one triangle, candidate segments of the same direction parity
/// that pairwise meet can hold at most one selected separatrix. A greedy clique cover of these
/// conflicts gives constraints that imply every pairwise Eq. 3 inside the triangle and make the
/// LP relaxation much tighter than the pairs alone.
std::set<std::vector<int>> conflictCliques(const SeparatrixGraph& h, const std::vector<int>& variableOf) {
  struct Piece {
    int variable;
    const PathSegment* segment;
  };
  int maxFace = -1;
  for (const auto& a : h.arcs)
    for (const auto& s : a.path.segments) maxFace = std::max(maxFace, s.face);
  std::vector<std::vector<Piece>> perFace(maxFace + 1);
  for (int i = 0; i < int(h.arcs.size()); ++i) {
    if (variableOf[i] < 0) continue;
    for (const auto& s : h.arcs[i].path.segments)
      if (s.face >= 0) perFace[s.face].push_back({variableOf[i], &s});
  }
  std::set<std::vector<int>> cliques;
  for (auto& pieces : perFace) {
    if (pieces.size() < 2) continue;
    for (int parity = 0; parity < 2; ++parity) {
      std::vector<Piece> group;
      for (const auto& p : pieces)
        if (p.segment->direction % 2 == parity) group.push_back(p);
      const int n = int(group.size());
      if (n < 2) continue;
      std::vector<std::vector<char>> meets(n, std::vector<char>(n, 0));
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
          if (group[i].variable == group[j].variable) continue;
          const auto& s = *group[i].segment;
          const auto& t = *group[j].segment;
          meets[i][j] = meets[j][i] = relateChords(s.from, s.to, t.from, t.to) != ChordRelation::Disjoint;
        }
      std::vector<std::vector<char>> covered(n, std::vector<char>(n, 0));
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
          if (!meets[i][j] || covered[i][j]) continue;
          std::vector<int> members = {i, j};
          for (int k = 0; k < n; ++k) {
            if (k == i || k == j) continue;
            bool all = true;
            for (int m : members) all = all && meets[k][m];
            if (all) members.push_back(k);
          }
          for (int a : members)
            for (int b : members) covered[a][b] = 1;
          std::vector<int> vars;
          for (int m : members) vars.push_back(group[m].variable);
          std::sort(vars.begin(), vars.end());
          vars.erase(std::unique(vars.begin(), vars.end()), vars.end());
          if (vars.size() >= 2) cliques.insert(vars);
        }
    }
  }
  return cliques;
}

}  // namespace

SelectionResult selectSeparatrices(const SeparatrixGraph& h, const std::vector<char>& portFree, double timeLimitSeconds) {
  SelectionResult out;
  auto free = [&](int p) { return portFree.empty() || (p >= 0 && p < int(portFree.size()) && portFree[p]); };
  // Scale the objective so that coefficients are near 1 whatever the mesh units.
  double meanLength = 0;
  for (const auto& a : h.arcs) meanLength += a.length;
  meanLength = h.arcs.empty() ? 1 : meanLength / h.arcs.size();
  IntegerProgram ip;
  ip.setMaximize(true);
  std::vector<int> variableOf(h.arcs.size(), -1);
  std::vector<int> arcOf;
  std::vector<double> weight;
  for (int i = 0; i < int(h.arcs.size()); ++i) {
    const auto& a = h.arcs[i];
    if (!free(a.portA) || !free(a.portB) || !(a.length > 0)) continue;
    variableOf[i] = ip.addBinary(meanLength / a.length);
    arcOf.push_back(i);
    weight.push_back(meanLength / a.length);
  }
  const int n = int(arcOf.size());
  // Eq. 2: at most one separatrix per port.
  std::vector<std::vector<int>> portsOfVariable(n);
  for (int p = 0; p < int(h.arcsAtPort.size()); ++p) {
    std::vector<std::pair<int, double>> terms;
    for (int a : h.arcsAtPort[p])
      if (variableOf[a] >= 0) terms.push_back({variableOf[a], 1.0}), portsOfVariable[variableOf[a]].push_back(p);
    if (terms.size() > 1) ip.addConstraint(terms, IntegerProgram::Sense::LessEqual, 1.0);
  }
  // Eq. 3, as clique constraints per triangle; pairs that only conflict across... every
  // tangential pair meets in some triangle, so the cliques cover them all.
  for (const auto& clique : conflictCliques(h, variableOf)) {
    std::vector<std::pair<int, double>> terms;
    for (int v : clique) terms.push_back({v, 1.0});
    ip.addConstraint(terms, IntegerProgram::Sense::LessEqual, 1.0);
  }
  out.variables = ip.numVariables();
  out.constraints = ip.numConstraints();

  // A greedy solution (best ratio first) is the fallback if lp_solve cannot do better in time.
  std::vector<std::vector<int>> conflicts(n);
  for (const auto& pr : h.tangentialPairs) {
    int a = variableOf[pr.first], b = variableOf[pr.second];
    if (a >= 0 && b >= 0) conflicts[a].push_back(b), conflicts[b].push_back(a);
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weight[a] > weight[b]; });
  std::vector<char> taken(n, 0), portTaken(h.arcsAtPort.size(), 0);
  double greedyObjective = 0;
  for (int v : order) {
    bool ok = true;
    for (int p : portsOfVariable[v]) ok = ok && !portTaken[p];
    for (int w : conflicts[v]) ok = ok && !taken[w];
    if (!ok) continue;
    taken[v] = 1;
    for (int p : portsOfVariable[v]) portTaken[p] = 1;
    greedyObjective += weight[v];
  }

  IntegerProgram::Result r = ip.solve(timeLimitSeconds);
  out.status = r.status;
  out.message = r.message;
  out.seconds = r.seconds;
  bool useGreedy = !r.hasSolution() || r.objective < greedyObjective - 1e-9;
  if (useGreedy && (r.status == IntegerProgram::Status::Infeasible || r.status == IntegerProgram::Status::Unbounded))
    throw std::runtime_error("separatrix selection: " + r.message);  // impossible for this model: a bug
  if (useGreedy) {
    out.status = IntegerProgram::Status::TimeLimit;
    out.message = (r.message.empty() ? std::string("lp_solve stopped early") : r.message) +
                  "; the greedy selection (objective " + std::to_string(greedyObjective) + ") is used instead";
    for (int v = 0; v < n; ++v)
      if (taken[v]) out.selected.push_back(arcOf[v]);
  } else {
    for (int v = 0; v < n; ++v)
      if (r.values[v] > 0.5) out.selected.push_back(arcOf[v]);
  }
  std::sort(out.selected.begin(), out.selected.end());
  return out;
}

}  // namespace fcql
