#include "mesh/quad_mesh.h"

#include "util/union_find.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <sstream>
#include <unordered_set>

namespace fcql {
namespace {

/// Components of the faces (vertex lists), joined through shared vertices.
template <std::size_t N>
int countComponents(int numVertices, const std::vector<std::array<int, N>>& faces) {
  UnionFind sets(numVertices);
  std::vector<char> used(numVertices, 0);
  for (const auto& f : faces)
    for (std::size_t i = 0; i < N; ++i) {
      used[f[i]] = 1;
      sets.unite(f[i], f[0]);
    }
  int components = 0;
  for (int v = 0; v < numVertices; ++v) components += used[v] && sets.find(v) == v;
  return components;
}

/// Loops of border edges, given the next vertex along the border from each border vertex.
int countBorderLoops(const std::map<int, int>& borderNext) {
  int loops = 0;
  std::map<int, char> seen;
  for (const auto& b : borderNext) {
    if (seen.count(b.first)) continue;
    ++loops;
    for (int v = b.first; !seen.count(v);) {
      seen[v] = 1;
      auto next = borderNext.find(v);
      v = next != borderNext.end() ? next->second : b.first;
    }
  }
  return loops;
}

}  // namespace

SurfaceTopology triangleMeshTopology(int numVertices, const std::vector<std::array<int, 3>>& triangles) {
  SurfaceTopology t;
  // The directed edges as sorted keys (a, b) → a·2³² + b: a twin is found by binary search
  // (a std::map of pairs took a tenth of a second on a 40K-face mesh's layout).
  auto key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
  std::vector<std::uint64_t> directed;
  directed.reserve(3 * triangles.size());
  std::vector<char> used(numVertices, 0);
  for (const auto& f : triangles)
    for (int i = 0; i < 3; ++i) {
      directed.push_back(key(f[i], f[(i + 1) % 3]));
      used[f[i]] = 1;
    }
  std::sort(directed.begin(), directed.end());
  directed.erase(std::unique(directed.begin(), directed.end()), directed.end());
  long edges = 0;
  std::map<int, int> borderNext;
  for (const std::uint64_t e : directed) {
    const int a = int(e >> 32), b = int(e & 0xffffffffu);
    const bool twin = std::binary_search(directed.begin(), directed.end(), key(b, a));
    if (!twin || a < b) ++edges;
    if (!twin) borderNext[a] = b;
  }
  t.borderLoops = countBorderLoops(borderNext);
  long vertices = 0;
  for (char u : used) vertices += u;
  t.eulerCharacteristic = int(vertices - edges + long(triangles.size()));
  t.components = countComponents(numVertices, triangles);
  return t;
}

QuadMeshReport checkQuadMesh(const QuadMesh& mesh) {
  QuadMeshReport r;
  const int nv = mesh.numVertices();
  std::map<std::pair<int, int>, int> directed;  // (a,b) -> uses
  std::vector<int> valence(nv, 0), uses(nv, 0);
  for (const auto& q : mesh.quads)
    for (int i = 0; i < 4; ++i) {
      int a = q[i], b = q[(i + 1) % 4];
      if (a < 0 || a >= nv || a == b) {
        r.problem = "a quad has an invalid or repeated vertex";
        return r;
      }
      if (++directed[{a, b}] > 1) {
        r.problem = "the edge " + std::to_string(a) + "-" + std::to_string(b) + " is used twice in the same direction";
        return r;
      }
      uses[a] += 1;
    }
  long edges = 0;
  std::map<int, int> borderNext;
  for (const auto& e : directed) {
    bool twin = directed.count({e.first.second, e.first.first}) > 0;
    if (!twin || e.first.first < e.first.second) ++edges;
    valence[e.first.first] += 1;
    if (!twin) {
      valence[e.first.second] += 1;  // border edges count once at each end
      if (borderNext.count(e.first.first)) {
        r.problem = "vertex " + std::to_string(e.first.first) + " is non-manifold (two border fans)";
        return r;
      }
      borderNext[e.first.first] = e.first.second;
    }
  }
  r.borderLoops = countBorderLoops(borderNext);
  int used = 0;
  std::map<std::string, int> irregular;
  for (int v = 0; v < nv; ++v) {
    if (uses[v] == 0) {
      ++r.unusedVertices;
      continue;
    }
    ++used;
    bool border = borderNext.count(v) > 0;
    if ((!border && valence[v] != 4) || (border && valence[v] != 3 && valence[v] != 2)) {
      ++r.irregularVertices;
      ++irregular[(border ? "border " : "") + std::to_string(valence[v])];
    }
  }
  r.irregularByValence.assign(irregular.begin(), irregular.end());
  r.eulerCharacteristic = used - int(edges) + mesh.numQuads();
  r.components = countComponents(nv, mesh.quads);
  r.genus = (2 * r.components - r.eulerCharacteristic - r.borderLoops) / 2;
  r.manifold = true;
  return r;
}

std::string quadMeshToObj(const QuadMesh& mesh) {
  std::ostringstream out;
  out.precision(9);
  out << "# field-coherent quad mesh: " << mesh.numVertices() << " vertices, " << mesh.numQuads() << " quads\n";
  for (const auto& p : mesh.positions) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& q : mesh.quads) out << "f " << q[0] + 1 << ' ' << q[1] + 1 << ' ' << q[2] + 1 << ' ' << q[3] + 1 << '\n';
  return out.str();
}

void growAcrossQuads(const QuadMesh& mesh, std::vector<char>& marked, int rings) {
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> grown = marked;
    for (const auto& q : mesh.quads)
      if (marked[q[0]] || marked[q[1]] || marked[q[2]] || marked[q[3]])
        for (int v : q) grown[v] = 1;
    marked.swap(grown);
  }
}

std::vector<char> quadBorderVertices(const QuadMesh& mesh) {
  auto key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
  std::unordered_set<std::uint64_t> directed;
  directed.reserve(4 * mesh.quads.size());
  for (const auto& q : mesh.quads)
    for (int i = 0; i < 4; ++i) directed.insert(key(q[i], q[(i + 1) % 4]));
  std::vector<char> border(mesh.positions.size(), 0);
  for (const auto& q : mesh.quads)
    for (int i = 0; i < 4; ++i) {
      const int a = q[i], b = q[(i + 1) % 4];
      if (!directed.count(key(b, a))) border[a] = border[b] = 1;
    }
  return border;
}

}  // namespace fcql
