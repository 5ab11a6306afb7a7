#include "layout/independent_set_reduction.h"

#include <algorithm>
#include <stdexcept>

namespace fcql {

DominationResult removeDominatedVariables(const std::vector<std::vector<int>>& rows, const std::vector<double>& weight) {
  const int n = int(weight.size());
  DominationResult out;
  out.fixedToZero.assign(n, 0);
  // Neighbours of each variable: the others of every row it is in.
  std::vector<std::vector<int>> neighbours(n);
  for (const auto& row : rows)
    for (int a : row) {
      if (a < 0 || a >= n) throw std::out_of_range("removeDominatedVariables: a row names an unknown variable");
      for (int b : row)
        if (b != a) neighbours[a].push_back(b);
    }
  std::vector<int> degree(n);
  for (int v = 0; v < n; ++v) {
    auto& list = neighbours[v];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    degree[v] = int(list.size());
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
