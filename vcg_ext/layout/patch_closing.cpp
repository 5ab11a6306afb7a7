#include "layout/patch_closing.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <limits>
#include <unordered_map>

namespace fcql {
namespace {

/// The original vertex inside patch p that is farthest (in edge hops) from its boundary; −1
/// if the patch has no interior original vertex.
int centralVertex(const PatchLayout& patches, int p) {
  const int nv = int(patches.positions.size());
  std::vector<int> hops(nv, -1);
  std::vector<std::vector<int>> neighbours(nv);
  std::vector<char> inPatch(nv, 0);
  std::deque<int> queue;
  for (int t = 0; t < int(patches.triangles.size()); ++t) {
    if (patches.patch[t] != p) continue;
    const auto& tri = patches.triangles[t];
    for (int i = 0; i < 3; ++i) {
      int a = tri[i], b = tri[(i + 1) % 3];
      inPatch[a] = 1;
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
      if (patches.edgeCurve[t][i] != -1) {
        for (int v : {a, b})
          if (hops[v] < 0) hops[v] = 0, queue.push_back(v);
      }
    }
  }
  if (queue.empty())  // a closed patch (torus): start anywhere
    for (int v = 0; v < nv && queue.empty(); ++v)
      if (inPatch[v]) hops[v] = 0, queue.push_back(v);
  int best = -1, bestHops = -1;
  while (!queue.empty()) {
    int v = queue.front();
    queue.pop_front();
    if (v < patches.numOriginalVertices && hops[v] > bestHops) best = v, bestHops = hops[v];
    for (int w : neighbours[v])
      if (hops[w] < 0) hops[w] = hops[v] + 1, queue.push_back(w);
  }
  if (bestHops <= 0) {
    // No vertex strictly inside; for a closed patch any vertex will do.
    bool closed = true;
    for (int t = 0; t < int(patches.triangles.size()) && closed; ++t)
      if (patches.patch[t] == p)
        for (int i = 0; i < 3; ++i) closed = closed && patches.edgeCurve[t][i] == -1;
    return closed ? best : -1;
  }
  return best;
}

}  // namespace

TracedPath reversedPath(const TracedPath& path) {
  TracedPath r = path;
  std::reverse(r.points.begin(), r.points.end());
  std::reverse(r.segments.begin(), r.segments.end());
  for (auto& s : r.segments) {
    std::swap(s.from, s.to);
    s.direction = (s.direction + 2) % 4;
  }
  return r;
}

ClosingReport closeNonDiskPatches(const SurfaceMesh& mesh, const CrossField& field, FieldAnalysis& analysis,
                                  std::unique_ptr<GeodesicGraph>& graph, Layout& layout, PatchLayout& patches,
                                  int maxLines) {
  auto start = std::chrono::steady_clock::now();
  ClosingReport report;
  std::vector<char> triedVertex(mesh.numVertices(), 0);
  while (report.linesAdded < maxLines) {
    // The largest patch that is not a disk.
    int target = -1;
    for (int p = 0; p < patches.numPatches(); ++p)
      if (!patches.patches[p].isDisk && (target < 0 || patches.patches[p].triangles > patches.patches[target].triangles))
        target = p;
    if (target < 0) break;
    int v = centralVertex(patches, target);
    if (v < 0 || triedVertex[v] || analysis.vertexIndexQuarters[v] != 0 || mesh.isBorderVertex(v)) break;
    triedVertex[v] = 1;
    // Make v a virtual singularity and rebuild G with its ports.
    SingularVertex sv;
    sv.vertex = v;
    sv.indexQuarters = 0;
    sv.ports = computePorts(mesh, field, v);
    if (sv.ports.size() != 4) break;
    analysis.singularities.push_back(sv);
    graph = std::make_unique<GeodesicGraph>(mesh, field, analysis, graph->parameters(), GeodesicGraph::SinkDistances::Skipped);
    ++report.virtualVertices;
    const int first = graph->firstPort()[analysis.singularities.size() - 1];
    std::vector<int> ports = {first, first + 1, first + 2, first + 3};

    const BarrierSet barriers = layoutBarriers(*graph, layout);
    SearchOptions options;
    options.maxSinks = 1;
    options.barriers = &barriers;
    options.tJunctionMode = true;
    options.sinkAllowed.assign(graph->ports().size(), 0);
    std::vector<std::vector<TracedPath>> results(4);
    for (int q = 0; q < 4; ++q) {
      options.sinkAllowed.assign(graph->ports().size(), 0);
      options.sinkAllowed[ports[(q + 2) % 4]] = 1;
      results[q] = traceFromPort(*graph, ports[q], options);
    }
    auto endsOnBoundary = [&](int q) {
      return !results[q].empty() && results[q][0].end != TracedPath::Sink;
    };
    // A line through v between two opposite ports that both reach the boundary.
    int bestPair = -1;
    double bestLength = std::numeric_limits<double>::infinity();
    for (int q = 0; q < 2; ++q)
      if (endsOnBoundary(q) && endsOnBoundary(q + 2) && results[q][0].length + results[q + 2][0].length < bestLength)
        bestPair = q, bestLength = results[q][0].length + results[q + 2][0].length;
    if (bestPair >= 0) {
      const TracedPath& a = results[bestPair][0];
      const TracedPath& b = results[bestPair + 2][0];
      TracedPath line = reversedPath(a);
      line.points.pop_back();  // v appears once
      line.points.insert(line.points.end(), b.points.begin(), b.points.end());
      line.segments.insert(line.segments.end(), b.segments.begin(), b.segments.end());
      line.length = a.length + b.length;
      line.sourcePort = ports[bestPair];
      line.end = b.end;
      line.barrier = b.barrier;
      LayoutSeparatrix s;
      s.kind = LayoutSeparatrix::TJunction;
      s.portA = ports[bestPair];
      s.portB = ports[bestPair + 2];
      s.path = std::move(line);
      for (const TracedPath* end : {&a, &b})
        (end->end == TracedPath::Barrier ? layout.tJunctions : layout.borderConnections) += 1;
      layout.separatrices.push_back(std::move(s));
    } else {
      // The shortest loop closing at v.
      int bestLoop = -1;
      for (int q = 0; q < 4; ++q)
        if (!results[q].empty() && results[q][0].end == TracedPath::Sink &&
            (bestLoop < 0 || results[q][0].length < results[bestLoop][0].length))
          bestLoop = q;
      if (bestLoop < 0) break;
      LayoutSeparatrix s;
      s.kind = LayoutSeparatrix::Full;
      s.portA = ports[bestLoop];
      s.portB = results[bestLoop][0].sinkPort;
      s.path = results[bestLoop][0];
      layout.separatrices.push_back(std::move(s));
      // The other pair may close the patch now: try it from the same vertex.
      const BarrierSet more = layoutBarriers(*graph, layout);
      options.barriers = &more;
      int q = (bestLoop + 1) % 4;
      options.sinkAllowed.assign(graph->ports().size(), 0);
      options.sinkAllowed[ports[(q + 2) % 4]] = 1;
      auto second = traceFromPort(*graph, ports[q], options);
      if (!second.empty() && second[0].end == TracedPath::Sink) {
        LayoutSeparatrix t;
        t.kind = LayoutSeparatrix::Full;
        t.portA = ports[q];
        t.portB = second[0].sinkPort;
        t.path = second[0];
        layout.separatrices.push_back(std::move(t));
        ++report.linesAdded;
      }
    }
    ++report.linesAdded;
    patches = buildPatchLayout(*graph, layout);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace fcql
