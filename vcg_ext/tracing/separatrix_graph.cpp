#include "tracing/separatrix_graph.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

namespace fcql {

bool meetsItself(const TracedPath& path) {
  // Its pieces sorted by face: only a face the path enters twice or more is tested, pairwise.
  std::vector<std::pair<int, int>> byFace;  // (face, piece)
  byFace.reserve(path.segments.size());
  for (int i = 0; i < int(path.segments.size()); ++i)
    if (path.segments[i].face >= 0) byFace.emplace_back(path.segments[i].face, i);
  std::sort(byFace.begin(), byFace.end());
  for (std::size_t first = 0, end; first < byFace.size(); first = end) {
    for (end = first + 1; end < byFace.size() && byFace[end].first == byFace[first].first;) ++end;
    for (std::size_t i = first; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j) {
        const PathSegment &a = path.segments[byFace[i].second], &b = path.segments[byFace[j].second];
        if ((a.direction - b.direction) % 2 == 0 && relateChords(a.from, a.to, b.from, b.to) != ChordRelation::Disjoint)
          return true;
      }
  }
  return false;
}

SeparatrixGraph buildSeparatrixGraph(const GeodesicGraph& graph, const std::vector<std::vector<TracedPath>>& searches) {
  // Best path per unordered pair of ports.
  std::map<std::pair<int, int>, const TracedPath*> best;
  for (const auto& search : searches)
    for (const TracedPath& p : search) {
      if (p.end != TracedPath::Sink || p.sinkPort < 0 || meetsItself(p)) continue;
      std::pair<int, int> key(std::min(p.sourcePort, p.sinkPort), std::max(p.sourcePort, p.sinkPort));
      auto it = best.find(key);
      if (it == best.end() || p.length < it->second->length ||
          (p.length == it->second->length && p.sourcePort < it->second->sourcePort))
        best[key] = &p;
    }
  SeparatrixGraph h;
  h.arcsAtPort.assign(graph.ports().size(), {});
  for (const auto& entry : best) {
    CandidateSeparatrix c;
    c.portA = entry.second->sourcePort;
    c.portB = entry.second->sinkPort;
    c.length = entry.second->length;
    c.path = *entry.second;
    int id = int(h.arcs.size());
    h.arcsAtPort[c.portA].push_back(id);
    if (c.portB != c.portA) h.arcsAtPort[c.portB].push_back(id);
    h.arcs.push_back(std::move(c));
  }
  classifyCrossings(graph.mesh(), h, graph.parameters().threads);
  return h;
}

SeparatrixGraph traceCandidateSeparatrices(const GeodesicGraph& graph, const ProgressCallback& progress) {
  std::vector<int> ports(graph.ports().size());
  std::iota(ports.begin(), ports.end(), 0);
  SearchOptions options;
  options.maxSinks = graph.parameters().k;
  return buildSeparatrixGraph(graph, traceFromPorts(graph, ports, options, progress));
}

}  // namespace fcql
