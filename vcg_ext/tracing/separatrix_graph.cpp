#include "tracing/separatrix_graph.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

namespace fcql {

bool meetsItself(const TracedPath& path) {
  // Pieces by face; a face the path enters twice is tested pairwise.
  std::unordered_map<int, std::vector<const PathSegment*>> byFace;
  for (const auto& s : path.segments)
    if (s.face >= 0) byFace[s.face].push_back(&s);
  for (const auto& entry : byFace) {
    const auto& pieces = entry.second;
    for (std::size_t i = 0; i < pieces.size(); ++i)
      for (std::size_t j = i + 1; j < pieces.size(); ++j)
        if ((pieces[i]->direction - pieces[j]->direction) % 2 == 0 &&
            relateChords(pieces[i]->from, pieces[i]->to, pieces[j]->from, pieces[j]->to) != ChordRelation::Disjoint)
          return true;
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
