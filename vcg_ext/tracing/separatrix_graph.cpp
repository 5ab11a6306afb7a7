#include "tracing/separatrix_graph.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

namespace fcql {

SeparatrixGraph buildSeparatrixGraph(const GeodesicGraph& graph, const std::vector<std::vector<TracedPath>>& searches) {
  // Best path per unordered pair of ports.
  std::map<std::pair<int, int>, const TracedPath*> best;
  for (const auto& search : searches)
    for (const TracedPath& p : search) {
      if (p.end != TracedPath::Sink || p.sinkPort < 0) continue;
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
