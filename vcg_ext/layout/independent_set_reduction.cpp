#include "layout/independent_set_reduction.h"

#include <algorithm>
#include <stdexcept>

namespace fcql {

DominationResult removeDominatedVariables(const std::vector<std::vector<int>>& rows, const std::vector<double>& weight) {
  const int n = int(weight.size());
  DominationResult out;
  out.fixedToZero.assign(n, 0);
  // Neighbours of each variable: the others of every row it is in, each once (rows of
  // neighbouring triangles overlap heavily: a stamp per variable drops the repeats).
  std::vector<std::vector<int>> rowsOf(n);
  for (int r = 0; r < int(rows.size()); ++r)
    for (int a : rows[r]) {
      if (a < 0 || a >= n) throw std::out_of_range("removeDominatedVariables: a row names an unknown variable");
      rowsOf[a].push_back(r);
    }
  std::vector<std::vector<int>> neighbours(n);
  std::vector<int> degree(n), stamp(n, -1);
  for (int a = 0; a < n; ++a) {
    stamp[a] = a;
    for (int r : rowsOf[a])
      for (int b : rows[r])
        if (stamp[b] != a) stamp[b] = a, neighbours[a].push_back(b);
    degree[a] = int(neighbours[a].size());
  }
  std::vector<char>& removed = out.fixedToZero;
  std::vector<int> mark(n, -1);  // mark[x] == u: x is in N[u] (set while u is examined)
  for (bool changed = true; changed;) {
    changed = false;
    ++out.rounds;
    for (int u = 0; u < n; ++u) {
      if (removed[u] || degree[u] == 0) continue;
      mark[u] = u;
      for (int x : neighbours[u]) mark[x] = u;  // removed ones too: they are skipped below
      for (int v : neighbours[u]) {
        // N[v] ⊆ N[u] needs deg v ≤ deg u (both counted among the variables left).
        if (removed[v] || weight[v] < weight[u] || degree[v] > degree[u]) continue;
        bool inside = true;
        for (int x : neighbours[v])
          if (!removed[x] && mark[x] != u) {
            inside = false;
            break;
          }
        if (!inside) continue;
        removed[u] = 1;
        ++out.fixed;
        for (int x : neighbours[u]) --degree[x];
        changed = true;
        break;
      }
    }
  }
  return out;
}

}  // namespace fcql
