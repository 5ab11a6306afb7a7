#include "mesh/vertex_welding.h"

#include <algorithm>
#include <numeric>

namespace fcql {

VertexWelding weldCoincidentVertices(const SurfaceMesh& mesh) {
  VertexWelding w;
  const std::vector<Vec3>& positions = mesh.positions();
  const int nv = int(positions.size());
  // Sort by position; the first vertex (lowest index) of each run of equal positions stays.
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const Vec3 &p = positions[a], &q = positions[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> representative(nv);
  for (int i = 0; i < nv; ++i) {
    const int v = order[i];
    const bool same = i > 0 && positions[order[i - 1]] == positions[v];
    representative[v] = same ? representative[order[i - 1]] : v;
    w.merged += same ? 1 : 0;
  }
  if (w.merged == 0) return w;
  std::vector<int> newIndex(nv, -1);
  std::vector<Vec3> kept;
  kept.reserve(nv - w.merged);
  for (int v = 0; v < nv; ++v)
    if (representative[v] == v) newIndex[v] = int(kept.size()), kept.push_back(positions[v]);
  for (int v = 0; v < nv; ++v) newIndex[v] = newIndex[representative[v]];
  std::vector<std::array<int, 3>> faces = mesh.faces();
  for (auto& f : faces)
    for (int& v : f) v = newIndex[v];
  try {
    w.mesh = SurfaceMesh(std::move(kept), std::move(faces));
    w.newIndex = std::move(newIndex);
    w.welded = true;
  } catch (const MeshError& e) {
    w.problem = e.what();
  }
  return w;
}

std::string VertexWelding::note() const {
  if (merged == 0) return "";
  const std::string count = std::to_string(merged) + (merged == 1 ? " vertex lies" : " vertices lie") +
                            " exactly on another vertex";
  if (welded) return count + ": merged (an unwelded mesh), the faces keep their order";
  return "warning: " + count + ", but merging them would make the mesh invalid (" + problem +
         "): they are kept apart, and the surface stays cut there";
}

}  // namespace fcql
