#include "quadrangulation/patch_sides.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace fcql {

PatchGraph buildPatchGraph(const PatchLayout& layout) {
  PatchGraph g;
  g.patches.resize(layout.numPatches());
  g.numLayoutVertices = int(layout.positions.size());
  std::map<std::pair<int, int>, int> segmentOfEdge;  // undirected first edge of a segment -> id
  for (int p = 0; p < layout.numPatches(); ++p) {
    const PatchReport& rep = layout.patches[p];
    // A disk with 4 corners is a quad patch; a disk with 3 or more other corners is an n-gon,
    // kept whole here and split into n quads by splitPolygonPatches().
    const bool polygon = !rep.valid && rep.isDisk && rep.corners >= 3;
    if (!rep.valid && !polygon)
      throw std::runtime_error("patch " + std::to_string(p) + " cannot be quadrangulated: " + rep.problem);
    const int m = int(rep.loop.size());
    int first = -1;
    for (int k = 0; k < m && first < 0; ++k)
      if (rep.loopCorner[k]) first = k;
    if (first < 0) throw std::runtime_error("patch " + std::to_string(p) + " has no corner on its boundary");
    PatchSides& ps = g.patches[p];
    ps.layoutPatch = p;
    int side = -1;
    std::vector<int> chain;
    int chainStart = 0;
    auto closeSegment = [&]() {
      if (chain.size() < 2) return;
      // The same key from both sides: the smaller of the chain's two end edges.
      const std::size_t last = chain.size() - 1;
      auto key = std::min(std::make_pair(std::min(chain[0], chain[1]), std::max(chain[0], chain[1])),
                          std::make_pair(std::min(chain[last], chain[last - 1]), std::max(chain[last], chain[last - 1])));
      auto it = segmentOfEdge.find(key);
      if (it == segmentOfEdge.end()) {
        LayoutSegment s;
        s.vertices = chain;
        for (int v : chain) s.polyline.push_back(layout.positions[v]);
        for (std::size_t i = 1; i < chain.size(); ++i)
          s.length += (layout.positions[chain[i]] - layout.positions[chain[i - 1]]).norm();
        s.nodeA = chain.front();
        s.nodeB = chain.back();
        s.patchA = p;
        int id = int(g.segments.size());
        g.segments.push_back(std::move(s));
        segmentOfEdge[key] = id;
        ps.sides[polygon ? 0 : side].push_back({id, false, chainStart});
      } else {
        LayoutSegment& s = g.segments[it->second];
        std::vector<int> reversed(chain.rbegin(), chain.rend());
        if (s.vertices != reversed || s.patchB >= 0)
          throw std::runtime_error("patch " + std::to_string(p) + ": its sides do not match its neighbour's");
        s.patchB = p;
        ps.sides[polygon ? 0 : side].push_back({it->second, true, chainStart});
      }
      chain.clear();
    };
    for (int step = 0; step <= m; ++step) {
      const int k = (first + step) % m;
      const int v = rep.loop[k];
      if (!chain.empty()) chain.push_back(v);
      if (step == m) {  // back at the first corner
        closeSegment();
        break;
      }
      const bool isPatchCorner = rep.loopCorner[k];
      if (isPatchCorner || layout.corner[v]) {
        closeSegment();
        if (isPatchCorner) {
          ++side;
          if (!polygon && side > 3) throw std::runtime_error("patch " + std::to_string(p) + " has more than 4 corners");
          if (side <= 3) ps.corners[side] = v;
        }
        chain.assign(1, v);
        chainStart = k;
      }
    }
    if (polygon) {
      ps.polygonCorners = side + 1;
      ps.original = false;
    } else if (side != 3) {
      throw std::runtime_error("patch " + std::to_string(p) + " does not have 4 corners");
    }
    // A boundary that runs along a segment and straight back is a slit: a separatrix ending
    // inside the patch (at a singularity whose other separatrices are missing). Its grid
    // would fold onto itself.
    std::vector<SideSegment> around;
    for (const auto& list : ps.sides) around.insert(around.end(), list.begin(), list.end());
    for (std::size_t i = 0; i < around.size() && around.size() > 1; ++i) {
      const SideSegment& a = around[i];
      const SideSegment& b = around[(i + 1) % around.size()];
      if (a.segment == b.segment && a.reversed != b.reversed) {
        const LayoutSegment& seg = g.segments[a.segment];
        const int tip = a.reversed ? seg.nodeA : seg.nodeB;
        throw std::runtime_error("patch " + std::to_string(p) + " has a slit: a separatrix ends inside it, at vertex " +
                                 std::to_string(tip) + " (a singularity left with fewer separatrices than ports); it cannot be cut into quads");
      }
    }
  }
  return g;
}

}  // namespace fcql
