#include "quadrangulation/zero_chains.h"

#include "quadrangulation/patch_map.h"
#include "quadrangulation/patch_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

namespace fcql {
namespace {

double polylineLength(const std::vector<Vec3>& p) {
  double l = 0;
  for (std::size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
  return l;
}

/// Splits polyline at arc-length fraction f into [start..x] and [x..end].
std::pair<std::vector<Vec3>, std::vector<Vec3>> splitPolyline(const std::vector<Vec3>& p, double f) {
  double target = polylineLength(p) * f, run = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    double len = (p[i] - p[i - 1]).norm();
    if (run + len >= target || i + 1 == p.size()) {
      double t = len > 0 ? std::clamp((target - run) / len, 0.0, 1.0) : 0;
      Vec3 x = p[i - 1] + (p[i] - p[i - 1]) * t;
      std::vector<Vec3> a(p.begin(), p.begin() + i), b(p.begin() + i, p.end());
      a.push_back(x);
      b.insert(b.begin(), x);
      return {a, b};
    }
    run += len;
  }
  return {p, p};
}

class Splitter {
public:
  Splitter(PatchGraph& g, const PatchLayout& layout) : g_(g), layout_(layout) {
    for (int t = 0; t < int(layout.triangles.size()); ++t) {
      trianglesOf_[layout.patch[t]].push_back(t);
      for (int i = 0; i < 3; ++i)
        halfEdge_[PatchMap::edgeKey(layout.triangles[t][i], layout.triangles[t][(i + 1) % 3])] = t * 3 + i;
    }
  }

  void split(int p) {
    // Copy: the vector of patches grows below.
    PatchSides parent = g_.patches[p];
    const double um = 0.5 * (parent.u0 + parent.u1), vm = 0.5 * (parent.v0 + parent.v1);
    std::array<std::vector<SideSegment>, 4> firstHalf, secondHalf;
    std::array<int, 4> mid{};
    for (int k = 0; k < 4; ++k) splitSide(p, k, firstHalf[k], secondHalf[k], mid[k]);
    const PatchMap& map = unitMap(parent.layoutPatch);
    const std::array<Vec2, 4> midUv = {Vec2(um, parent.v0), Vec2(parent.u1, vm), Vec2(um, parent.v1), Vec2(parent.u0, vm)};
    const Vec2 centreUv(um, vm);
    const int centre = addNode(map.pointAt(centreUv));
    // Inner segments I_k from the middle of side k to the centre.
    std::array<int, 4> inner{};
    for (int k = 0; k < 4; ++k) {
      LayoutSegment s;
      const int samples = 16;
      s.polyline.push_back(g_.nodePosition(layout_, mid[k]));
      for (int i = 1; i < samples; ++i) s.polyline.push_back(map.pointAt(midUv[k] + (centreUv - midUv[k]) * (double(i) / samples)));
      s.polyline.push_back(g_.nodePosition(layout_, centre));
      s.length = polylineLength(s.polyline);
      s.nodeA = mid[k];
      s.nodeB = centre;
      inner[k] = int(g_.segments.size());
      g_.segments.push_back(std::move(s));
    }
    // The four parts (corners counter-clockwise in the unit square).
    auto child = [&](double u0, double u1, double v0, double v1, std::array<std::vector<SideSegment>, 4> sides,
                     std::array<int, 4> corners) {
      PatchSides c;
      c.sides = std::move(sides);
      c.corners = corners;
      c.layoutPatch = parent.layoutPatch;
      c.u0 = u0, c.u1 = u1, c.v0 = v0, c.v1 = v1;
      c.original = false;
      c.forceEqual = true;
      int id = int(g_.patches.size());
      g_.patches.push_back(std::move(c));
      return id;
    };
    auto fwd = [](int s) { return std::vector<SideSegment>{{s, false, 0}}; };
    auto rev = [](int s) { return std::vector<SideSegment>{{s, true, 0}}; };
    const auto& C = parent.corners;
    int c00 = child(parent.u0, um, parent.v0, vm, {firstHalf[0], fwd(inner[0]), rev(inner[3]), secondHalf[3]},
                    {C[0], mid[0], centre, mid[3]});
    int c10 = child(um, parent.u1, parent.v0, vm, {secondHalf[0], firstHalf[1], fwd(inner[1]), rev(inner[0])},
                    {mid[0], C[1], mid[1], centre});
    int c11 = child(um, parent.u1, vm, parent.v1, {rev(inner[1]), secondHalf[1], firstHalf[2], fwd(inner[2])},
                    {centre, mid[1], C[2], mid[2]});
    int c01 = child(parent.u0, um, vm, parent.v1, {fwd(inner[3]), rev(inner[2]), secondHalf[2], firstHalf[3]},
                    {mid[3], centre, mid[2], C[3]});
    g_.patches[p].active = false;
    // Who is on each side of each segment now.
    std::array<int, 4> children = {c00, c10, c11, c01};
    for (int c : children)
      for (const auto& side : g_.patches[c].sides)
        for (const auto& ss : side) {
          LayoutSegment& s = g_.segments[ss.segment];
          if (s.patchA == p) s.patchA = c;
          else if (s.patchB == p) s.patchB = c;
          else if (s.patchA < 0) s.patchA = c;
          else if (s.patchB < 0 && s.patchA != c) s.patchB = c;
        }
  }

private:
  int addNode(const Vec3& x) {
    g_.extraNodes.push_back(x);
    return g_.numLayoutVertices + int(g_.extraNodes.size()) - 1;
  }

  const PatchMap& unitMap(int layoutPatch) {
    auto& m = maps_[layoutPatch];
    if (!m) {
      std::vector<Vec2> unit = unitSquareBoundary(layout_, layoutPatch);
      m = std::make_unique<PatchMap>(layout_, layoutPatch, trianglesOf_[layoutPatch], halfEdge_,
                                     [&](int k) { return unit[k]; });
    }
    return *m;
  }

  /// Halves side k of patch p at its arc-length middle, splitting the segment there (in every
  /// patch that uses it) unless the middle is next to an existing node.
  void splitSide(int p, int k, std::vector<SideSegment>& first, std::vector<SideSegment>& second, int& middle) {
    const std::vector<SideSegment> side = g_.patches[p].sides[k];
    double total = 0;
    for (const auto& ss : side) total += g_.segments[ss.segment].length;
    if (side.size() > 1) {
      // The side carries t-junctions: split it at the one nearest to its middle, which removes
      // that t-junction (it becomes a regular crossing with the new inner segment).
      double run = 0, best = std::numeric_limits<double>::infinity();
      std::size_t at = 1;
      for (std::size_t i = 0; i + 1 < side.size(); ++i) {
        run += g_.segments[side[i].segment].length;
        if (std::abs(run - 0.5 * total) < best) best = std::abs(run - 0.5 * total), at = i + 1;
      }
      const SideSegment& ss = side[at];
      middle = ss.reversed ? g_.segments[ss.segment].nodeB : g_.segments[ss.segment].nodeA;
      first.assign(side.begin(), side.begin() + at);
      second.assign(side.begin() + at, side.end());
      return;
    }
    double run = 0;
    for (std::size_t i = 0; i < side.size(); ++i) {
      const SideSegment ss = side[i];
      const LayoutSegment seg = g_.segments[ss.segment];
      if (run + seg.length < 0.5 * total && i + 1 < side.size()) {
        first.push_back(ss);
        run += seg.length;
        continue;
      }
      double f = seg.length > 0 ? (0.5 * total - run) / seg.length : 0.5;  // along the side's direction
      if (f < 0.1 && i > 0) {  // the node before this segment is close enough
        middle = ss.reversed ? seg.nodeB : seg.nodeA;
        second.assign(side.begin() + i, side.end());
        return;
      }
      if (f > 0.9 && i + 1 < side.size()) {
        first.push_back(ss);
        middle = ss.reversed ? seg.nodeA : seg.nodeB;
        second.assign(side.begin() + i + 1, side.end());
        return;
      }
      // Split the segment (in its own orientation) and replace it wherever it is used.
      double fs = ss.reversed ? 1 - f : f;
      auto halves = splitPolyline(seg.polyline, fs);
      middle = addNode(halves.first.back());
      LayoutSegment a, b;
      a.polyline = halves.first;
      b.polyline = halves.second;
      a.length = polylineLength(a.polyline);
      b.length = polylineLength(b.polyline);
      a.nodeA = seg.nodeA, a.nodeB = middle;
      b.nodeA = middle, b.nodeB = seg.nodeB;
      a.patchA = b.patchA = seg.patchA;
      a.patchB = b.patchB = seg.patchB;
      const int ia = int(g_.segments.size()), ib = ia + 1;
      g_.segments.push_back(std::move(a));
      g_.segments.push_back(std::move(b));
      for (int owner : {seg.patchA, seg.patchB}) {
        if (owner < 0) continue;
        PatchSides& ps = g_.patches[owner];
        for (auto& list : ps.sides)
          for (std::size_t j = 0; j < list.size(); ++j) {
            if (list[j].segment != ss.segment) continue;
            bool r = list[j].reversed;
            std::vector<SideSegment> repl = r ? std::vector<SideSegment>{{ib, true, 0}, {ia, true, 0}}
                                              : std::vector<SideSegment>{{ia, false, 0}, {ib, false, 0}};
            list.erase(list.begin() + j);
            list.insert(list.begin() + j, repl.begin(), repl.end());
            break;
          }
        if (owner != p) {
          ps.original = false;  // its side now has a node it did not have
          ps.forceEqual = true;
        }
      }
      // The halves, from the updated side list.
      const auto& updated = g_.patches[p].sides[k];
      first.clear();
      second.clear();
      bool before = true;
      for (const auto& e : updated) {
        (before ? first : second).push_back(e);
        if ((e.reversed ? g_.segments[e.segment].nodeA : g_.segments[e.segment].nodeB) == middle) before = false;
      }
      return;
    }
    throw std::runtime_error("cannot find the middle of a patch side");
  }

  PatchGraph& g_;
  const PatchLayout& layout_;
  std::map<int, std::vector<int>> trianglesOf_;
  std::unordered_map<std::uint64_t, int> halfEdge_;
  std::map<int, std::unique_ptr<PatchMap>> maps_;
};

}  // namespace

void splitPatches(PatchGraph& graph, const PatchLayout& layout, const std::vector<int>& patches) {
  Splitter splitter(graph, layout);
  for (int p : patches)
    if (graph.patches[p].active) splitter.split(p);
}

}  // namespace fcql
