// Disjoint sets over 0..n−1 (path halving): the connected components of faces, patches, chord
// classes and linked programs throughout the library.
#pragma once

#include <numeric>
#include <vector>

namespace fcql {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  /// Joins the sets of a and b; b's root becomes the root of both.
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace fcql
