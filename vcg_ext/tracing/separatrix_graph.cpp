#include "tracing/separatrix_graph.h"

#include "mesh/worker_threads.h"

#include <algorithm>
#include <atomic>
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

void classifyCrossings(const SurfaceMesh& mesh, SeparatrixGraph& h, int threads) {
  struct Piece {
    int arc;
    const PathSegment* segment;
  };
  // Per face and direction parity, the pieces of paths in it: only pieces of the same parity
  // (the same or opposite directions) can meet tangentially. Orthogonal meetings constrain
  // nothing, and testing them took 40% of the time.
  std::vector<std::vector<Piece>> perFace(2 * std::size_t(mesh.numFaces()));
  auto listOf = [&](const PathSegment& s) -> std::vector<Piece>& { return perFace[2 * std::size_t(s.face) + (s.direction & 1)]; };
  for (int a = 0; a < int(h.arcs.size()); ++a)
    for (const PathSegment& s : h.arcs[a].path.segments)
      if (s.face >= 0) listOf(s).push_back({a, &s});
  // For each arc a, the arcs b > a it meets tangentially in some face; pairs come out ordered
  // by (a, b). A marker per arc replaces sorting every meeting. The arcs are shared out in
  // blocks among the threads, each block's pairs kept apart and joined in block order, so the
  // result does not depend on the number of threads.
  const int n = int(h.arcs.size());
  const int blockSize = 64;
  const int numBlocks = (n + blockSize - 1) / blockSize;
  std::vector<std::vector<std::pair<int, int>>> blocks(numBlocks);
  std::atomic<int> nextBlock{0};
  auto work = [&](int) {
    std::vector<char> met(n, 0);
    std::vector<int> others;
    for (int block; (block = nextBlock.fetch_add(1)) < numBlocks;) {
      auto& out = blocks[block];
      for (int a = block * blockSize, end = std::min(n, a + blockSize); a < end; ++a) {
        for (const PathSegment& s : h.arcs[a].path.segments) {
          if (s.face < 0) continue;
          for (const Piece& piece : listOf(s)) {
            // Near a singularity a face holds many paths: a pair known to meet is not tested again.
            if (piece.arc <= a || met[piece.arc]) continue;
            const PathSegment& t = *piece.segment;
            if (relateChords(s.from, s.to, t.from, t.to) == ChordRelation::Disjoint) continue;
            others.push_back(piece.arc);
            met[piece.arc] = 1;
          }
        }
        std::sort(others.begin(), others.end());
        for (int b : others) {
          out.emplace_back(a, b);
          met[b] = 0;
        }
        others.clear();
      }
    }
  };
  runOnWorkerThreads(workerThreadCount(threads, numBlocks), work);
  h.tangentialPairs.clear();
  for (const auto& b : blocks) h.tangentialPairs.insert(h.tangentialPairs.end(), b.begin(), b.end());
}

}  // namespace fcql
