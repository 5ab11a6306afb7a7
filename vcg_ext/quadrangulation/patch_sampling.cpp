#include "quadrangulation/patch_sampling.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace fcql {
namespace {

/// Points at fractions k/n (k = 1..n−1) of the arc length along a polyline.
std::vector<Vec3> samplesAlong(const std::vector<Vec3>& poly, int n) {
  std::vector<double> acc(poly.size(), 0);
  for (std::size_t i = 1; i < poly.size(); ++i) acc[i] = acc[i - 1] + (poly[i] - poly[i - 1]).norm();
  std::vector<Vec3> out;
  std::size_t seg = 1;
  for (int k = 1; k < n; ++k) {
    double target = acc.back() * k / n;
    while (seg + 1 < poly.size() && acc[seg] < target) ++seg;
    double len = acc[seg] - acc[seg - 1];
    double t = len > 0 ? (target - acc[seg - 1]) / len : 0;
    out.push_back(poly[seg - 1] + (poly[seg] - poly[seg - 1]) * std::clamp(t, 0.0, 1.0));
  }
  return out;
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

QuadMesh samplePatches(const PatchLayout& layout, const PatchGraph& graph, const SideLengths& lengths) {
  if (!lengths.inconsistentPatches.empty())
    throw std::runtime_error(std::to_string(lengths.inconsistentPatches.size()) +
                             " patches have opposite sides of different lengths (zero chains)");
  QuadMesh q;
  // Nodes (segment ends) and segment samples get their quad-mesh vertices once.
  std::unordered_map<int, int> nodeVertex;
  auto node = [&](int layoutVertex) {
    auto it = nodeVertex.find(layoutVertex);
    if (it != nodeVertex.end()) return it->second;
    q.positions.push_back(layout.positions[layoutVertex]);
    return nodeVertex[layoutVertex] = q.numVertices() - 1;
  };
  std::vector<std::vector<int>> segmentSamples(graph.segments.size());
  for (int s = 0; s < int(graph.segments.size()); ++s) {
    std::vector<Vec3> poly;
    for (int v : graph.segments[s].vertices) poly.push_back(layout.positions[v]);
    for (const Vec3& p : samplesAlong(poly, lengths.segments[s])) {
      q.positions.push_back(p);
      segmentSamples[s].push_back(q.numVertices() - 1);
    }
  }
  // Half-edges of the layout mesh, to join the triangles of a patch across inner edges.
  auto key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
  std::unordered_map<std::uint64_t, int> halfEdge;
  for (int t = 0; t < int(layout.triangles.size()); ++t)
    for (int i = 0; i < 3; ++i) halfEdge[key(layout.triangles[t][i], layout.triangles[t][(i + 1) % 3])] = t * 3 + i;
  // Triangles of each patch.
  std::vector<std::vector<int>> trianglesOf(layout.numPatches());
  for (int t = 0; t < int(layout.triangles.size()); ++t) trianglesOf[layout.patch[t]].push_back(t);

  for (int p = 0; p < layout.numPatches(); ++p) {
    const PatchSides& ps = graph.patches[p];
    const int W = lengths.sideLength(graph, p, 0), H = lengths.sideLength(graph, p, 1);
    // Grid vertex ids: (W+1) × (H+1); the boundary ones from nodes and segment samples.
    std::vector<int> grid((W + 1) * (H + 1), -1);
    auto at = [&](int i, int j) -> int& { return grid[j * (W + 1) + i]; };
    auto sidePoint = [&](int k, int c) -> int& {  // c along side k from its first corner
      switch (k) {
        case 0: return at(c, 0);
        case 1: return at(W, c);
        case 2: return at(W - c, H);
        default: return at(0, H - c);
      }
    };
    // Wedges: the copies of a vertex inside the patch, separated by its boundary (a vertex
    // the boundary loop meets twice, as on a cut through a cylinder, has two).
    const auto& tris = trianglesOf[p];
    std::unordered_map<int, int> slotOf;  // t*3+c -> local slot
    std::vector<int> parent;
    for (int t : tris)
      for (int c = 0; c < 3; ++c) {
        slotOf[t * 3 + c] = int(parent.size());
        parent.push_back(int(parent.size()));
      }
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    auto cornerIn = [&](int t, int v) {
      for (int c = 0; c < 3; ++c)
        if (layout.triangles[t][c] == v) return c;
      return -1;
    };
    for (int t : tris)
      for (int i = 0; i < 3; ++i) {
        if (layout.edgeCurve[t][i] != -1) continue;
        int a = layout.triangles[t][i], b = layout.triangles[t][(i + 1) % 3];
        auto it = halfEdge.find(key(b, a));
        if (it == halfEdge.end()) continue;
        int t2 = it->second / 3;
        parent[find(slotOf[t * 3 + i])] = find(slotOf[t2 * 3 + cornerIn(t2, a)]);
        parent[find(slotOf[t * 3 + (i + 1) % 3])] = find(slotOf[t2 * 3 + cornerIn(t2, b)]);
      }
    auto wedge = [&](int t, int c) { return find(slotOf[t * 3 + c]); };
    const PatchReport& rep = layout.patches[p];
    const int loopSize = int(rep.loop.size());
    auto loopWedge = [&](int k) {
      k %= loopSize;
      return wedge(rep.loopTriangle[k], cornerIn(rep.loopTriangle[k], rep.loop[k]));
    };
    // UV of the boundary wedges.
    std::unordered_map<int, Vec2> uvOf;
    auto sideUv = [&](int k, double c) {
      switch (k) {
        case 0: return Vec2(c, 0);
        case 1: return Vec2(W, c);
        case 2: return Vec2(W - c, H);
        default: return Vec2(0, H - c);
      }
    };
    for (int k = 0; k < 4; ++k) {
      int offset = 0;
      for (const SideSegment& ss : ps.sides[k]) {
        const LayoutSegment& seg = graph.segments[ss.segment];
        const int n = lengths.segments[ss.segment];
        std::vector<int> chain = seg.vertices;
        if (ss.reversed) std::reverse(chain.begin(), chain.end());
        sidePoint(k, offset) = node(chain.front());
        for (int m = 1; m < n; ++m)
          sidePoint(k, offset + m) = segmentSamples[ss.segment][ss.reversed ? n - 1 - m : m - 1];
        double total = seg.length, run = 0;
        for (std::size_t i = 0; i < chain.size(); ++i) {
          if (i > 0) run += (layout.positions[chain[i]] - layout.positions[chain[i - 1]]).norm();
          uvOf[loopWedge(ss.loopStart + int(i))] = sideUv(k, offset + (total > 0 ? n * run / total : 0));
        }
        offset += n;
      }
    }
    // Mean-value mapping of the interior wedges.
    std::unordered_map<int, int> interior;
    std::vector<int> interiorWedge;
    for (int t : tris)
      for (int c = 0; c < 3; ++c) {
        int w = wedge(t, c);
        if (!uvOf.count(w) && !interior.count(w)) {
          interior[w] = int(interiorWedge.size());
          interiorWedge.push_back(w);
        }
      }
    const int ni = int(interiorWedge.size());
    if (ni > 0) {
      std::vector<Eigen::Triplet<double>> entries;
      Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
      std::vector<double> diagonal(ni, 0);
      for (int t : tris) {
        const auto& tri = layout.triangles[t];
        for (int c = 0; c < 3; ++c) {
          auto it = interior.find(wedge(t, c));
          if (it == interior.end()) continue;
          const Vec3& pa = layout.positions[tri[c]];
          for (int other : {1, 2}) {
            int cb = (c + other) % 3, cd = (c + 3 - other) % 3;
            Vec3 eb = layout.positions[tri[cb]] - pa, ed = layout.positions[tri[cd]] - pa;
            double angle = std::atan2(eb.cross(ed).norm(), eb.dot(ed));
            double w = std::tan(angle / 2) / std::max(eb.norm(), 1e-300);
            diagonal[it->second] += w;
            int wb = wedge(t, cb);
            auto jt = interior.find(wb);
            if (jt != interior.end()) entries.emplace_back(it->second, jt->second, -w);
            else rhs.row(it->second) += w * uvOf.at(wb).transpose();
          }
        }
      }
      for (int i = 0; i < ni; ++i) entries.emplace_back(i, i, diagonal[i]);
      Eigen::SparseMatrix<double> A(ni, ni);
      A.setFromTriplets(entries.begin(), entries.end());
      Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
      solver.compute(A);
      if (solver.info() != Eigen::Success) throw std::runtime_error("patch " + std::to_string(p) + ": its mapping failed");
      Eigen::MatrixXd uv = solver.solve(rhs);
      for (int i = 0; i < ni; ++i) uvOf[interiorWedge[i]] = Vec2(uv(i, 0), uv(i, 1));
    }
    // Interior grid points: locate in the mapped triangles.
    for (int j = 1; j < H; ++j)
      for (int i = 1; i < W; ++i) {
        Vec2 x(i, j);
        int best = -1;
        double bestMin = -1e300, b0 = 0, b1 = 0, b2 = 0;
        for (int t : tris) {
          const Vec2 &A = uvOf[wedge(t, 0)], &B = uvOf[wedge(t, 1)], &C = uvOf[wedge(t, 2)];
          double area = cross2(B - A, C - A);
          if (std::abs(area) < 1e-300) continue;
          double l0 = cross2(B - x, C - x) / area, l1 = cross2(C - x, A - x) / area, l2 = 1 - l0 - l1;
          double mn = std::min({l0, l1, l2});
          if (mn > bestMin) bestMin = mn, best = t, b0 = l0, b1 = l1, b2 = l2;
          if (mn >= 0) break;
        }
        if (best < 0 || bestMin < -1e-6)
          throw std::runtime_error("patch " + std::to_string(p) + ": a grid point falls outside its mapping");
        const auto& tri = layout.triangles[best];
        q.positions.push_back(b0 * layout.positions[tri[0]] + b1 * layout.positions[tri[1]] + b2 * layout.positions[tri[2]]);
        at(i, j) = q.numVertices() - 1;
      }
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        q.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        q.quadPatch.push_back(p);
      }
  }
  return q;
}

}  // namespace fcql
