#include "quadrangulation/patch_sampling.h"

#include "quadrangulation/patch_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
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

/// Image of the point at side coordinate c on side k of a W × H rectangle.
Vec2 sideUv(int k, double c, double W, double H) {
  switch (k) {
    case 0: return Vec2(c, 0);
    case 1: return Vec2(W, c);
    case 2: return Vec2(W - c, H);
    default: return Vec2(0, H - c);
  }
}

}  // namespace

std::vector<Vec2> unitSquareBoundary(const PatchLayout& layout, int p) {
  const PatchReport& rep = layout.patches[p];
  const int m = int(rep.loop.size());
  int first = 0;
  while (first < m && !rep.loopCorner[first]) ++first;
  std::vector<Vec2> uv(m);
  // Sides by loop positions, each normalised by its arc length.
  int side = -1;
  std::vector<int> positions;
  auto flush = [&](int k, int closing) {
    if (positions.empty()) return;
    std::vector<double> acc(1, 0);
    for (std::size_t i = 1; i < positions.size(); ++i)
      acc.push_back(acc.back() + (layout.positions[rep.loop[positions[i]]] - layout.positions[rep.loop[positions[i - 1]]]).norm());
    double total = acc.back() + (layout.positions[rep.loop[closing]] - layout.positions[rep.loop[positions.back()]]).norm();
    for (std::size_t i = 0; i < positions.size(); ++i) uv[positions[i]] = sideUv(k, total > 0 ? acc[i] / total : 0, 1, 1);
    positions.clear();
  };
  for (int step = 0; step < m; ++step) {
    int k = (first + step) % m;
    if (rep.loopCorner[k]) {
      flush(side, k);
      ++side;
    }
    positions.push_back(k);
  }
  flush(side, first);
  return uv;
}

QuadMesh samplePatches(const PatchLayout& layout, const PatchGraph& graph, const SideLengths& lengths) {
  if (!lengths.inconsistentPatches.empty())
    throw std::runtime_error(std::to_string(lengths.inconsistentPatches.size()) +
                             " patches have opposite sides of different lengths (zero chains)");
  QuadMesh q;
  std::unordered_map<int, int> nodeVertex;
  auto node = [&](int id) {
    auto it = nodeVertex.find(id);
    if (it != nodeVertex.end()) return it->second;
    q.positions.push_back(graph.nodePosition(layout, id));
    return nodeVertex[id] = q.numVertices() - 1;
  };
  // Samples of the segments used by the patches, made once and shared by both sides.
  std::vector<std::vector<int>> segmentSamples(graph.segments.size());
  std::vector<char> sampled(graph.segments.size(), 0);
  for (const auto& ps : graph.patches) {
    if (!ps.active) continue;
    for (const auto& side : ps.sides)
      for (const auto& ss : side) {
        if (sampled[ss.segment]) continue;
        sampled[ss.segment] = 1;
        for (const Vec3& p : samplesAlong(graph.segments[ss.segment].polyline, lengths.segments[ss.segment])) {
          q.positions.push_back(p);
          segmentSamples[ss.segment].push_back(q.numVertices() - 1);
        }
      }
  }
  std::unordered_map<std::uint64_t, int> halfEdge;
  for (int t = 0; t < int(layout.triangles.size()); ++t)
    for (int i = 0; i < 3; ++i)
      halfEdge[PatchMap::edgeKey(layout.triangles[t][i], layout.triangles[t][(i + 1) % 3])] = t * 3 + i;
  std::vector<std::vector<int>> trianglesOf(layout.numPatches());
  for (int t = 0; t < int(layout.triangles.size()); ++t) trianglesOf[layout.patch[t]].push_back(t);
  std::map<int, std::unique_ptr<PatchMap>> unitMaps;   // layout patch -> map onto [0,1]²
  std::map<int, std::unique_ptr<PatchMap>> chartMaps;  // polygon chart -> its map

  for (int p = 0; p < int(graph.patches.size()); ++p) {
    const PatchSides& ps = graph.patches[p];
    if (!ps.active) continue;
    const int W = lengths.sideLength(graph, p, 0), H = lengths.sideLength(graph, p, 1);
    std::vector<int> grid((W + 1) * (H + 1), -1);
    auto at = [&](int i, int j) -> int& { return grid[j * (W + 1) + i]; };
    auto sidePoint = [&](int k, int c) -> int& {
      switch (k) {
        case 0: return at(c, 0);
        case 1: return at(W, c);
        case 2: return at(W - c, H);
        default: return at(0, H - c);
      }
    };
    std::vector<Vec2> loopUv;
    if (ps.original) loopUv.assign(layout.patches[ps.layoutPatch].loop.size(), Vec2::Zero());
    for (int k = 0; k < 4; ++k) {
      int offset = 0;
      for (const SideSegment& ss : ps.sides[k]) {
        const LayoutSegment& seg = graph.segments[ss.segment];
        const int n = lengths.segments[ss.segment];
        sidePoint(k, offset) = node(ss.reversed ? seg.nodeB : seg.nodeA);
        for (int m = 1; m < n; ++m) sidePoint(k, offset + m) = segmentSamples[ss.segment][ss.reversed ? n - 1 - m : m - 1];
        if (ps.original) {  // the segment's layout vertices go where its samples are
          std::vector<int> chain = seg.vertices;
          if (ss.reversed) std::reverse(chain.begin(), chain.end());
          const int loopSize = int(loopUv.size());
          double run = 0;
          for (std::size_t i = 0; i < chain.size(); ++i) {
            if (i > 0) run += (layout.positions[chain[i]] - layout.positions[chain[i - 1]]).norm();
            loopUv[(ss.loopStart + int(i)) % loopSize] = sideUv(k, offset + (seg.length > 0 ? n * run / seg.length : 0), W, H);
          }
        }
        offset += n;
      }
    }
    if (ps.original) {
      // The patch mapped onto its integer rectangle: grid lines meet the sides at their samples.
      PatchMap map(layout, ps.layoutPatch, trianglesOf[ps.layoutPatch], halfEdge, [&](int k) { return loopUv[k]; });
      for (int j = 1; j < H; ++j)
        for (int i = 1; i < W; ++i) {
          q.positions.push_back(map.pointAt(Vec2(i, j)));
          at(i, j) = q.numVertices() - 1;
        }
      q.outsidePoints += map.outsidePoints();
    } else if (ps.chart >= 0) {
      // A part of a split patch: bilinear in its quad of the layout patch's polygon chart.
      auto& map = chartMaps[ps.chart];
      if (!map) {
        const PolygonChart& chart = graph.charts[ps.chart];
        map = std::make_unique<PatchMap>(layout, chart.layoutPatch, trianglesOf[chart.layoutPatch], halfEdge,
                                         [&](int k) { return chart.loopUv[k]; });
      }
      const auto& c = ps.chartCorners;
      for (int j = 1; j < H; ++j)
        for (int i = 1; i < W; ++i) {
          const double s = double(i) / W, t = double(j) / H;
          const Vec2 uv = c[0] * ((1 - s) * (1 - t)) + c[1] * (s * (1 - t)) + c[2] * (s * t) + c[3] * ((1 - s) * t);
          q.positions.push_back(map->pointAt(uv));
          at(i, j) = q.numVertices() - 1;
        }
    } else {
      // A whole layout patch whose sides gained nodes from a neighbour's split: its unit-square map.
      auto& map = unitMaps[ps.layoutPatch];
      if (!map) {
        std::vector<Vec2> unit = unitSquareBoundary(layout, ps.layoutPatch);
        map = std::make_unique<PatchMap>(layout, ps.layoutPatch, trianglesOf[ps.layoutPatch], halfEdge,
                                         [&](int k) { return unit[k]; });
      }
      for (int j = 1; j < H; ++j)
        for (int i = 1; i < W; ++i) {
          q.positions.push_back(map->pointAt(Vec2(double(i) / W, double(j) / H)));
          at(i, j) = q.numVertices() - 1;
        }
    }
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        q.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        q.quadPatch.push_back(ps.layoutPatch);
      }
  }
  for (const auto& m : unitMaps) q.outsidePoints += m.second->outsidePoints();
  for (const auto& m : chartMaps) q.outsidePoints += m.second->outsidePoints();
  return q;
}

}  // namespace fcql
