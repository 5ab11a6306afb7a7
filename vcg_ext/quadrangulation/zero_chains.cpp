#include "quadrangulation/zero_chains.h"

#include "quadrangulation/patch_map.h"
#include "quadrangulation/patch_sampling.h"
#include "util/math_constants.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

namespace fcql {
namespace {

/// A vertex of a chart's n-gon that no loop position maps onto (the layout's loop has no vertex
/// where a split put the node: a side too short to hold one) leaves the n-gon's corner there
/// uncovered, since the loop's image crosses it along a chord; mean-value coordinates then map
/// the patch onto less than the n-gon, and grid points near that corner fall outside the map
/// (deckel at half size: 36 points, 7 folded quads). Each such vertex moves onto the chord, on
/// its ray from the n-gon's centre: the chart's boundary is then the loop's image, still convex.
void fitVerticesToLoop(std::vector<Vec2>& vertex, const std::vector<Vec2>& loopUv) {
  const int m = int(loopUv.size());
  if (m < 3) return;
  auto wrap = [](double a) {  // into [0, 2π)
    a = std::fmod(a, 2 * kPi);
    return a < 0 ? a + 2 * kPi : a;
  };
  std::vector<double> angle(m);
  for (int k = 0; k < m; ++k) angle[k] = std::atan2(loopUv[k].y(), loopUv[k].x());
  for (Vec2& v : vertex) {
    const bool onLoop = std::any_of(loopUv.begin(), loopUv.end(), [&](const Vec2& u) { return (u - v).norm() < 1e-9; });
    if (onLoop) continue;
    const double a = std::atan2(v.y(), v.x());
    const Vec2 ray(std::cos(a), std::sin(a));
    for (int k = 0; k < m; ++k) {
      const Vec2 &A = loopUv[k], &B = loopUv[(k + 1) % m];
      if (!(wrap(a - angle[k]) < wrap(angle[(k + 1) % m] - angle[k]))) continue;
      const Vec2 d = B - A;
      const double den = d.x() * ray.y() - d.y() * ray.x();
      if (std::abs(den) < 1e-15) break;
      const double s = -(A.x() * ray.y() - A.y() * ray.x()) / den;
      v = A + std::clamp(s, 0.0, 1.0) * d;
      break;
    }
  }
}

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

  /// Charts the n-gon patch p now, while its segments are still the layout's own.
  void chart(int p) {
    PatchSides& ps = g_.patches[p];
    std::vector<SideSegment> edges;
    for (const auto& side : ps.sides) edges.insert(edges.end(), side.begin(), side.end());
    std::vector<Vec2> nodeUv;
    ps.chart = addChart(ps, edges, nodeUv);
  }

  /// Splits patch p like a Catmull–Clark n-gon: every boundary segment halved, inner segments
  /// from the middles to a centre, one quad part per boundary node.
  void split(int p) {
    PatchSides parent = g_.patches[p];  // copy: the vectors grow below
    reuseHalvedSegments(p, parent);
    const std::vector<SideSegment> edges = ngonEdges(parent);
    const int n = int(edges.size());
    std::vector<Vec2> nodeUv(n);
    const int chart = chartNodes(parent, edges, nodeUv);
    const PatchMap& map = chartMap(chart);
    Vec2 centreUv = Vec2::Zero();
    for (const Vec2& uv : nodeUv) centreUv += uv / double(n);
    const int centre = addNode(map.pointAt(centreUv));
    const Halves halves = halveBoundary(p, edges, nodeUv);
    const std::vector<int> inner = innerSegments(map, halves, centre, centreUv);
    addParts(p, parent, edges, chart, halves, inner, centre, nodeUv, centreUv);
  }

private:
  /// The boundary segments of a patch being split, halved: first/second half in the patch's
  /// direction of travel, the middle node and its chart position, per boundary edge.
  struct Halves {
    std::vector<SideSegment> first, second;
    std::vector<int> middle;
    std::vector<Vec2> middleUv;
  };

  /// Segments halved by a neighbour split in the same round are whole edges of this n-gon
  /// again: their halves and middle node are reused, so that the round splits its patches
  /// at once and leaves no t-junction between two of them.
  void reuseHalvedSegments(int p, PatchSides& parent) const {
    for (auto& side : parent.sides)
      for (std::size_t j = 0; j + 1 < side.size(); ++j) {
        auto it = halfOf_.find(side[j].segment);
        if (it == halfOf_.end()) continue;
        const std::array<int, 3>& h = halved_.at(it->second);
        const bool forward = !side[j].reversed && side[j].segment == h[0] && side[j + 1].segment == h[1] && !side[j + 1].reversed;
        const bool backward = side[j].reversed && side[j].segment == h[1] && side[j + 1].segment == h[0] && side[j + 1].reversed;
        if (!forward && !backward) continue;
        side[j] = replacedSide_.at({p, it->second});
        side.erase(side.begin() + j + 1);
      }
  }

  /// The boundary as an n-gon: its segments in order. Throws for fewer than 3 or a slit.
  static std::vector<SideSegment> ngonEdges(const PatchSides& parent) {
    std::vector<SideSegment> edges;
    for (const auto& side : parent.sides) edges.insert(edges.end(), side.begin(), side.end());
    const int n = int(edges.size());
    if (n < 3) throw std::runtime_error("zero chains: a patch with fewer than 3 boundary segments");
    for (int i = 0; i < n; ++i)
      if (edges[i].segment == edges[(i + 1) % n].segment)
        throw std::runtime_error("patch " + std::to_string(parent.layoutPatch) +
                                 " has a slit (a separatrix ends inside it): it cannot be cut into quads");
    return edges;
  }

  /// The chart of the patch (a new one if it has none) and the chart position of each node.
  int chartNodes(const PatchSides& parent, const std::vector<SideSegment>& edges, std::vector<Vec2>& nodeUv) {
    int chart = parent.chart;
    if (chart < 0) {
      chart = addChart(parent, edges, nodeUv);
    } else if (parent.polygonCorners > 0) {
      nodesBetweenKnownOnes(chart, edges, nodeUv);
    } else {
      nodesOnQuadSides(parent, nodeUv);
    }
    return chart;
  }

  /// A whole n-gon patch charted before its neighbours were split: the chart's vertices are
  /// known, the nodes added since lie between them by arc length.
  void nodesBetweenKnownOnes(int chart, const std::vector<SideSegment>& edges, std::vector<Vec2>& nodeUv) const {
    const int n = int(edges.size());
    const auto& known = g_.charts[chart].nodeUv;
    std::vector<int> node(n);
    std::vector<double> at(n + 1, 0);
    for (int i = 0; i < n; ++i) {
      const SideSegment& e = edges[i];
      node[i] = e.reversed ? g_.segments[e.segment].nodeB : g_.segments[e.segment].nodeA;
      at[i + 1] = at[i] + g_.segments[e.segment].length;
    }
    int first = -1;
    for (int i = 0; i < n && first < 0; ++i)
      if (known.count(node[i])) first = i;
    if (first < 0) throw std::runtime_error("zero chains: a charted patch lost its corners");
    for (int step = 0; step < n;) {
      const int a = (first + step) % n;
      int gap = 1;
      while (!known.count(node[(a + gap) % n])) ++gap;
      const Vec2 ua = known.at(node[a]), ub = known.at(node[(a + gap) % n]);
      auto arc = [&](int k) { return at[(a + k) % n] + (a + k >= n ? at[n] : 0.0); };
      const double span = arc(gap) - arc(0);
      for (int k = 0; k < gap; ++k) {
        const double t = span > 0 ? (arc(k) - arc(0)) / span : 0.0;
        nodeUv[(a + k) % n] = ua * (1 - t) + ub * t;
      }
      step += gap;
    }
  }

  /// A part split again: its nodes lie on the straight sides of its quad in the chart.
  void nodesOnQuadSides(const PatchSides& parent, std::vector<Vec2>& nodeUv) const {
    int e = 0;
    for (int k = 0; k < 4; ++k) {
      double total = 0, run = 0;
      for (const auto& ss : parent.sides[k]) total += g_.segments[ss.segment].length;
      for (const auto& ss : parent.sides[k]) {
        const double t = total > 0 ? run / total : 0;
        nodeUv[e++] = parent.chartCorners[k] * (1 - t) + parent.chartCorners[(k + 1) % 4] * t;
        run += g_.segments[ss.segment].length;
      }
    }
  }

  /// Halves every boundary segment of patch p (each segment once).
  Halves halveBoundary(int p, const std::vector<SideSegment>& edges, const std::vector<Vec2>& nodeUv) {
    const int n = int(edges.size());
    Halves h;
    h.first.resize(n);
    h.second.resize(n);
    h.middle.resize(n);
    h.middleUv.resize(n);
    for (int i = 0; i < n; ++i) {
      const SideSegment ss = edges[i];
      // A segment is halved once: a patch whose boundary meets itself (a torus cut open into
      // one patch) uses it twice, and a neighbour split in the same round may have halved it.
      auto it = halved_.find(ss.segment);
      if (it == halved_.end()) {
        int a, b;
        const int m = splitSegment(ss.segment, p, a, b);
        it = halved_.emplace(ss.segment, std::array<int, 3>{{a, b, m}}).first;
        halfOf_[a] = halfOf_[b] = ss.segment;
      }
      const int a = it->second[0], b = it->second[1];
      h.middle[i] = it->second[2];
      h.first[i] = ss.reversed ? SideSegment{b, true, 0} : SideSegment{a, false, 0};
      h.second[i] = ss.reversed ? SideSegment{a, true, 0} : SideSegment{b, false, 0};
      h.middleUv[i] = 0.5 * (nodeUv[i] + nodeUv[(i + 1) % n]);
    }
    return h;
  }

  /// Inner segments from each middle to the centre, straight in the chart.
  std::vector<int> innerSegments(const PatchMap& map, const Halves& h, int centre, const Vec2& centreUv) {
    const int n = int(h.middle.size());
    std::vector<int> inner(n);
    for (int i = 0; i < n; ++i) {
      LayoutSegment s;
      const int samples = 16;
      s.polyline.push_back(g_.nodePosition(layout_, h.middle[i]));
      for (int j = 1; j < samples; ++j)
        s.polyline.push_back(map.pointAt(h.middleUv[i] + (centreUv - h.middleUv[i]) * (double(j) / samples)));
      s.polyline.push_back(g_.nodePosition(layout_, centre));
      s.length = polylineLength(s.polyline);
      s.nodeA = h.middle[i];
      s.nodeB = centre;
      inner[i] = int(g_.segments.size());
      g_.segments.push_back(std::move(s));
    }
    return inner;
  }

  /// One part per node i (where edge i−1 ends and edge i starts): middle(i−1), node i,
  /// middle(i), centre. Patch p is retired; the segments name the parts as their patches.
  void addParts(int p, const PatchSides& parent, const std::vector<SideSegment>& edges, int chart, const Halves& h,
                const std::vector<int>& inner, int centre, const std::vector<Vec2>& nodeUv, const Vec2& centreUv) {
    const int n = int(edges.size());
    g_.patches[p].active = false;
    for (int i = 0; i < n; ++i) {
      const int prev = (i + n - 1) % n;
      PatchSides c;
      c.sides = {std::vector<SideSegment>{h.second[prev]}, std::vector<SideSegment>{h.first[i]},
                 std::vector<SideSegment>{{inner[i], false, 0}}, std::vector<SideSegment>{{inner[prev], true, 0}}};
      const SideSegment& e = edges[i];
      const int node = e.reversed ? g_.segments[e.segment].nodeB : g_.segments[e.segment].nodeA;
      c.corners = {h.middle[prev], node, h.middle[i], centre};
      c.layoutPatch = parent.layoutPatch;
      c.chart = chart;
      c.chartCorners = {h.middleUv[prev], nodeUv[i], h.middleUv[i], centreUv};
      c.original = false;
      c.forceEqual = true;
      const int id = int(g_.patches.size());
      g_.patches.push_back(std::move(c));
      for (const auto& side : g_.patches[id].sides)
        for (const auto& ss : side) {
          LayoutSegment& s = g_.segments[ss.segment];
          if (s.patchA == p) s.patchA = id;
          else if (s.patchB == p) s.patchB = id;
          else if (s.patchA < 0) s.patchA = id;
          else if (s.patchB < 0 && s.patchA != id) s.patchB = id;
        }
    }
  }

  int addNode(const Vec3& x) {
    g_.extraNodes.push_back(x);
    return g_.numLayoutVertices + int(g_.extraNodes.size()) - 1;
  }

  /// Maps the whole layout patch of `parent` onto a regular n-gon, edge i ← segment edges[i]
  /// by arc length; fills the chart position of each node.
  int addChart(const PatchSides& parent, const std::vector<SideSegment>& edges, std::vector<Vec2>& nodeUv) {
    const int n = int(edges.size());
    std::vector<Vec2> vertex(n);
    for (int i = 0; i < n; ++i) vertex[i] = Vec2(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n));
    const PatchReport& rep = layout_.patches[parent.layoutPatch];
    const int m = int(rep.loop.size());
    PolygonChart chart;
    chart.layoutPatch = parent.layoutPatch;
    chart.loopUv.resize(m);
    // The n-gon's vertices go where the loop's image passes them (fitVerticesToLoop), then
    // are the chart positions of the nodes.
    auto finish = [&] {
      fitVerticesToLoop(vertex, chart.loopUv);
      nodeUv = vertex;
      for (int e = 0; e < n; ++e)
        chart.nodeUv[edges[e].reversed ? g_.segments[edges[e].segment].nodeB : g_.segments[edges[e].segment].nodeA] = vertex[e];
      g_.charts.push_back(std::move(chart));
      return int(g_.charts.size()) - 1;
    };
    if (std::all_of(edges.begin(), edges.end(), [&](const SideSegment& e) { return !g_.segments[e.segment].vertices.empty(); })) {
      // Segments of the layout itself: each covers the loop positions from its loopStart on.
      for (int e = 0; e < n; ++e) {
        std::vector<int> chain = g_.segments[edges[e].segment].vertices;
        if (edges[e].reversed) std::reverse(chain.begin(), chain.end());
        const double total = g_.segments[edges[e].segment].length;
        double run = 0;
        for (std::size_t i = 0; i < chain.size(); ++i) {
          if (i > 0) run += (layout_.positions[chain[i]] - layout_.positions[chain[i - 1]]).norm();
          const double t = total > 0 ? std::clamp(run / total, 0.0, 1.0) : 0.0;
          chart.loopUv[(edges[e].loopStart + int(i)) % m] = vertex[e] * (1 - t) + vertex[(e + 1) % n] * t;
        }
      }
      return finish();
    }
    // Some segments were halved by neighbours' splits: arc-length position of every loop vertex
    // along its side (as unitSquareBoundary walks it), then along the segments of that side.
    int first = 0;
    while (first < m && !rep.loopCorner[first]) ++first;
    std::vector<int> sideOf(m, 0);
    std::vector<double> along(m, 0);
    int side = -1;
    double run = 0;
    for (int step = 0; step < m; ++step) {
      const int k = (first + step) % m;
      if (rep.loopCorner[k]) {
        ++side;
        run = 0;
      } else {
        run += (layout_.positions[rep.loop[k]] - layout_.positions[rep.loop[(k + m - 1) % m]]).norm();
      }
      sideOf[k] = std::min(side, 3);
      along[k] = run;
    }
    // The segments of each side with their arc-length ranges, mapped onto the n-gon's edges.
    std::array<int, 4> firstEdge{};
    for (int k = 0, e = 0; k < 4; ++k) {
      firstEdge[k] = e;
      e += int(parent.sides[k].size());
    }
    for (int pos = 0; pos < m; ++pos) {
      const int k = sideOf[pos];
      const auto& segs = parent.sides[k];
      double start = 0;
      std::size_t j = 0;
      while (j + 1 < segs.size() && along[pos] > start + g_.segments[segs[j].segment].length) {
        start += g_.segments[segs[j].segment].length;
        ++j;
      }
      const double length = g_.segments[segs[j].segment].length;
      const double t = length > 0 ? std::clamp((along[pos] - start) / length, 0.0, 1.0) : 0.0;
      const int e = firstEdge[k] + int(j);
      chart.loopUv[pos] = vertex[e] * (1 - t) + vertex[(e + 1) % n] * t;
    }
    return finish();
  }

  const PatchMap& chartMap(int chart) {
    auto& m = maps_[chart];
    if (!m) {
      const PolygonChart& c = g_.charts[chart];
      m = std::make_unique<PatchMap>(layout_, c.layoutPatch, trianglesOf_[c.layoutPatch], halfEdge_,
                                     [&](int k) { return c.loopUv[k]; });
    }
    return *m;
  }

  /// Halves segment `s` at its arc-length middle: segments a (nodeA → middle) and b (middle →
  /// nodeB) replace it wherever it is used. Patches other than `splitting` that use it gain a
  /// t-junction and get hard opposite-side equalities. Returns the middle node.
  int splitSegment(int s, int splitting, int& a, int& b) {
    const LayoutSegment seg = g_.segments[s];
    auto halves = splitPolyline(seg.polyline, 0.5);
    const int middle = addNode(halves.first.back());
    LayoutSegment first, second;
    first.polyline = halves.first;
    second.polyline = halves.second;
    first.length = polylineLength(first.polyline);
    second.length = polylineLength(second.polyline);
    first.nodeA = seg.nodeA, first.nodeB = middle;
    second.nodeA = middle, second.nodeB = seg.nodeB;
    first.patchA = second.patchA = seg.patchA;
    first.patchB = second.patchB = seg.patchB;
    a = int(g_.segments.size());
    b = a + 1;
    g_.segments.push_back(std::move(first));
    g_.segments.push_back(std::move(second));
    for (int owner : {seg.patchA, seg.patchB}) {
      if (owner < 0) continue;
      PatchSides& ps = g_.patches[owner];
      for (auto& list : ps.sides)
        for (std::size_t j = 0; j < list.size(); ++j) {
          if (list[j].segment != s) continue;
          if (owner != splitting) replacedSide_[{owner, s}] = list[j];
          const bool r = list[j].reversed;
          const std::vector<SideSegment> repl =
              r ? std::vector<SideSegment>{{b, true, 0}, {a, true, 0}} : std::vector<SideSegment>{{a, false, 0}, {b, false, 0}};
          list.erase(list.begin() + j);
          list.insert(list.begin() + j, repl.begin(), repl.end());
          ++j;
        }
      if (owner != splitting) {
        ps.original = false;  // its side now has a node it did not have
        ps.forceEqual = true;
      }
    }
    return middle;
  }

  PatchGraph& g_;
  const PatchLayout& layout_;
  std::map<int, std::vector<int>> trianglesOf_;
  std::unordered_map<std::uint64_t, int> halfEdge_;
  std::map<int, std::unique_ptr<PatchMap>> maps_;
  /// Segments halved by this splitter: segment → (first half, second half, middle node), and
  /// each half → its segment; the side entry each other owner had before, per (owner, segment).
  std::map<int, std::array<int, 3>> halved_;
  std::map<int, int> halfOf_;
  std::map<std::pair<int, int>, SideSegment> replacedSide_;
};

}  // namespace

int splitPolygonPatches(PatchGraph& graph, const PatchLayout& layout) {
  std::vector<int> polygons;
  for (int p = 0; p < int(graph.patches.size()); ++p)
    if (graph.patches[p].active && graph.patches[p].polygonCorners > 0) polygons.push_back(p);
  if (polygons.empty()) return 0;
  Splitter splitter(graph, layout);
  for (int p : polygons) splitter.chart(p);
  for (int p : polygons)
    if (graph.patches[p].active) splitter.split(p);
  return int(polygons.size());
}

void splitPatches(PatchGraph& graph, const PatchLayout& layout, const std::vector<int>& patches) {
  Splitter splitter(graph, layout);
  for (int p : patches)
    if (graph.patches[p].active) splitter.split(p);
}

}  // namespace fcql
