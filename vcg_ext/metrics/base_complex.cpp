#include "metrics/base_complex.h"

#include "util/union_find.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace fcql {
namespace {

/// The quad mesh's undirected edges with the quads on each side, and per vertex its edges.
struct EdgeGraph {
  struct Edge {
    int a = -1, b = -1;
    int quads[2] = {-1, -1};
    int numQuads = 0;
  };
  std::vector<Edge> edges;
  std::vector<std::vector<int>> vertexEdges;

  explicit EdgeGraph(const QuadMesh& mesh) : vertexEdges(mesh.positions.size()) {
    std::unordered_map<std::uint64_t, int> index;
    index.reserve(4 * mesh.quads.size());
    for (int q = 0; q < mesh.numQuads(); ++q)
      for (int i = 0; i < 4; ++i) {
        int a = mesh.quads[q][i], b = mesh.quads[q][(i + 1) % 4];
        if (a == b) throw std::invalid_argument("base complex: quad " + std::to_string(q) + " has a repeated vertex");
        if (a > b) std::swap(a, b);
        const std::uint64_t key = (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
        auto [it, fresh] = index.emplace(key, int(edges.size()));
        if (fresh) {
          edges.push_back({a, b, {-1, -1}, 0});
          vertexEdges[a].push_back(it->second);
          vertexEdges[b].push_back(it->second);
        }
        Edge& e = edges[it->second];
        if (e.numQuads == 2) throw std::invalid_argument("base complex: an edge is in more than two quads");
        e.quads[e.numQuads++] = q;
      }
  }

  int other(int e, int v) const { return edges[e].a == v ? edges[e].b : edges[e].a; }
  bool border(int e) const { return edges[e].numQuads == 1; }
  bool borderVertex(int v) const {
    for (int e : vertexEdges[v])
      if (border(e)) return true;
    return false;
  }
  /// Through regular interior vertex v (valence 4), the edge opposite e: the one that shares
  /// no quad with e.
  int opposite(int e, int v) const {
    for (int f : vertexEdges[v]) {
      if (f == e) continue;
      bool shares = false;
      for (int i = 0; i < edges[e].numQuads; ++i)
        for (int j = 0; j < edges[f].numQuads; ++j) shares |= edges[e].quads[i] == edges[f].quads[j];
      if (!shares) return f;
    }
    return -1;
  }
};

}  // namespace

BaseComplex measureBaseComplex(const QuadMesh& mesh) {
  const EdgeGraph graph(mesh);
  const int nv = mesh.numVertices();
  std::vector<char> border(nv, 0), irregular(nv, 0);
  for (int v = 0; v < nv; ++v) {
    const int valence = int(graph.vertexEdges[v].size());
    if (valence == 0) continue;
    border[v] = graph.borderVertex(v);
    irregular[v] = border[v] ? valence != 3 && valence != 2 : valence != 4;
  }

  BaseComplex result;
  std::vector<char> cut(graph.edges.size(), 0);  // edges the quads are not joined across
  for (std::size_t e = 0; e < graph.edges.size(); ++e) cut[e] = graph.border(int(e));
  for (int v = 0; v < nv; ++v) {
    if (!irregular[v]) continue;
    ++result.irregularVertices;
    for (int start : graph.vertexEdges[v]) {
      if (cut[start]) continue;  // a border edge, or a line already traced along it
      ++result.separatrices;
      for (int e = start, at = v;;) {
        cut[e] = 1;
        ++result.separatrixEdges;
        at = graph.other(e, at);
        if (irregular[at] || border[at]) break;
        e = graph.opposite(e, at);
        if (e < 0 || cut[e]) break;
      }
    }
  }

  UnionFind regions(mesh.numQuads());
  for (std::size_t e = 0; e < graph.edges.size(); ++e)
    if (!cut[e] && graph.edges[e].numQuads == 2) regions.unite(graph.edges[e].quads[0], graph.edges[e].quads[1]);
  for (int q = 0; q < mesh.numQuads(); ++q) result.patches += regions.find(q) == q;
  return result;
}

}  // namespace fcql
