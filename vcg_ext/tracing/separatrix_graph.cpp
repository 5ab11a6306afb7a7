#include "tracing/separatrix_graph.h"

#include <algorithm>
#include <cstdint>
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
  classifyCrossings(graph.mesh(), h);
  return h;
}

SeparatrixGraph traceCandidateSeparatrices(const GeodesicGraph& graph, const ProgressCallback& progress) {
  std::vector<int> ports(graph.ports().size());
  std::iota(ports.begin(), ports.end(), 0);
  SearchOptions options;
  options.maxSinks = graph.parameters().k;
  return buildSeparatrixGraph(graph, traceFromPorts(graph, ports, options, progress));
}

void classifyCrossings(const SurfaceMesh& mesh, SeparatrixGraph& h) {
  struct Piece {
    int arc;
    const PathSegment* segment;
  };
  std::vector<std::vector<Piece>> perFace(mesh.numFaces());
  for (int a = 0; a < int(h.arcs.size()); ++a)
    for (const PathSegment& s : h.arcs[a].path.segments)
      if (s.face >= 0) perFace[s.face].push_back({a, &s});
  // Every crossing of two arcs in a face, as (pair key, tangential); then one entry per pair,
  // tangential if any of its crossings is.
  std::vector<std::pair<std::uint64_t, char>> crossings;
  for (const auto& pieces : perFace)
    for (std::size_t i = 0; i < pieces.size(); ++i)
      for (std::size_t j = i + 1; j < pieces.size(); ++j) {
        if (pieces[i].arc == pieces[j].arc) continue;
        const PathSegment& s = *pieces[i].segment;
        const PathSegment& t = *pieces[j].segment;
        if (relateChords(s.from, s.to, t.from, t.to) == ChordRelation::Disjoint) continue;
        const std::uint64_t lo = std::uint32_t(std::min(pieces[i].arc, pieces[j].arc));
        const std::uint64_t hi = std::uint32_t(std::max(pieces[i].arc, pieces[j].arc));
        crossings.push_back({(lo << 32) | hi, char((s.direction - t.direction) % 2 == 0)});
      }
  std::sort(crossings.begin(), crossings.end());
  h.tangentialPairs.clear();
  h.orthogonalPairs.clear();
  for (std::size_t i = 0; i < crossings.size();) {
    const std::uint64_t key = crossings[i].first;
    bool tangential = false;
    for (; i < crossings.size() && crossings[i].first == key; ++i) tangential = tangential || crossings[i].second;
    const std::pair<int, int> pair(int(key >> 32), int(key & 0xffffffffu));
    (tangential ? h.tangentialPairs : h.orthogonalPairs).push_back(pair);
  }
}

}  // namespace fcql
