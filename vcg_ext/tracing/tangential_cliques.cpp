// Graph H's tangential crossings as conflict cliques (see classifyCrossings).
#include "util/worker_threads.h"
#include "tracing/separatrix_graph.h"

#include <algorithm>
#include <atomic>
#include <set>

namespace fcql {
namespace {

/// A piece of a candidate inside one triangle.
struct Piece {
  int arc;
  const PathSegment* segment;
};

using Cliques = std::set<std::vector<int>>;

/// A chord of a triangle and the arcs whose pieces run along it: paths through a face near a
/// singularity mostly share a few chords (on fertility 51M pairs of pieces, 260K pairs of
/// distinct chords), and pieces on one chord meet exactly what the chord meets.
struct ChordGroup {
  double from, to;
  std::vector<int> arcs;
};

/// Working memory of addTriangleCliques, reused from triangle to triangle.
struct CliqueScratch {
  std::vector<ChordGroup> chords;
  std::vector<char> meets, covered;  // m × m over the chords
  std::vector<int> members, arcs;
};

/// Adds the conflict cliques of one triangle's pieces: pieces of the same direction parity
/// that pairwise meet belong to arcs of which at most one can be selected. A greedy cover of
/// the meeting chords: each pair that meets and is not covered yet grows into a clique of all
/// chords meeting its members, and the clique holds every arc on those chords. A chord that
/// meets no other one still makes a clique of the arcs along it.
void addTriangleCliques(const std::vector<Piece>& pieces, CliqueScratch& w, Cliques& cliques) {
  for (int parity = 0; parity < 2; ++parity) {
    w.chords.clear();
    for (const auto& p : pieces) {
      if (p.segment->direction % 2 != parity) continue;
      const double a = std::min(p.segment->from, p.segment->to), b = std::max(p.segment->from, p.segment->to);
      auto it = std::find_if(w.chords.begin(), w.chords.end(), [&](const ChordGroup& c) { return c.from == a && c.to == b; });
      if (it == w.chords.end()) it = w.chords.insert(w.chords.end(), ChordGroup{a, b, {}});
      if (std::find(it->arcs.begin(), it->arcs.end(), p.arc) == it->arcs.end()) it->arcs.push_back(p.arc);
    }
    const int m = int(w.chords.size());
    if (m == 0) continue;
    w.meets.assign(std::size_t(m) * m, 0);
    w.covered.assign(std::size_t(m) * m, 0);
    auto at = [m](std::vector<char>& x, int i, int j) -> char& { return x[std::size_t(i) * m + j]; };
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        at(w.meets, i, j) = at(w.meets, j, i) =
            relateChords(w.chords[i].from, w.chords[i].to, w.chords[j].from, w.chords[j].to) != ChordRelation::Disjoint;
    auto emit = [&]() {
      w.arcs.clear();
      for (int c : w.members) w.arcs.insert(w.arcs.end(), w.chords[c].arcs.begin(), w.chords[c].arcs.end());
      std::sort(w.arcs.begin(), w.arcs.end());
      w.arcs.erase(std::unique(w.arcs.begin(), w.arcs.end()), w.arcs.end());
      if (w.arcs.size() >= 2) cliques.insert(w.arcs);
    };
    for (int i = 0; i < m; ++i) {
      bool alone = true;
      for (int j = 0; j < m && alone; ++j) alone = j == i || !at(w.meets, i, j);
      if (alone) {
        w.members = {i};
        emit();
        continue;
      }
      for (int j = i + 1; j < m; ++j) {
        if (!at(w.meets, i, j) || at(w.covered, i, j)) continue;
        w.members = {i, j};
        for (int k = 0; k < m; ++k) {
          if (k == i || k == j) continue;
          bool all = true;
          for (int c : w.members) all = all && at(w.meets, k, c);
          if (all) w.members.push_back(k);
        }
        for (int a : w.members)
          for (int b : w.members) at(w.covered, a, b) = 1;
        emit();
      }
    }
  }
}

/// The pairs (a < b) that share a clique, ordered by (a, b): each arc marks the arcs of its
/// cliques (fertility: 7K cliques, 7M visits, 0.01 s).
std::vector<std::pair<int, int>> pairsOfCliques(const std::vector<std::vector<int>>& cliques, int numArcs) {
  std::vector<std::vector<int>> cliquesOf(numArcs);
  for (int c = 0; c < int(cliques.size()); ++c)
    for (int a : cliques[c]) cliquesOf[a].push_back(c);
  std::vector<std::pair<int, int>> pairs;
  std::vector<char> met(numArcs, 0);
  std::vector<int> others;
  for (int a = 0; a < numArcs; ++a) {
    for (int c : cliquesOf[a])
      for (int b : cliques[c])
        if (b > a && !met[b]) met[b] = 1, others.push_back(b);
    std::sort(others.begin(), others.end());
    for (int b : others) {
      pairs.emplace_back(a, b);
      met[b] = 0;
    }
    others.clear();
  }
  return pairs;
}

}  // namespace

void classifyCrossings(const SurfaceMesh& mesh, SeparatrixGraph& h, int requestedThreads) {
  std::vector<std::vector<Piece>> perFace(mesh.numFaces());
  for (int a = 0; a < int(h.arcs.size()); ++a)
    for (const auto& s : h.arcs[a].path.segments)
      if (s.face >= 0) perFace[s.face].push_back({a, &s});
  // Triangles are shared out in blocks among the threads, each with its own set: the union
  // does not depend on who found what.
  const int numFaces = int(perFace.size());
  const int blockSize = 256;
  const int numBlocks = (numFaces + blockSize - 1) / blockSize;
  const int threads = workerThreadCount(requestedThreads, numBlocks);
  std::vector<Cliques> found(threads);
  std::atomic<int> nextBlock{0};
  auto work = [&](int thread) {
    CliqueScratch scratch;
    for (int block; (block = nextBlock.fetch_add(1)) < numBlocks;)
      for (int f = block * blockSize, end = std::min(numFaces, f + blockSize); f < end; ++f)
        if (perFace[f].size() >= 2) addTriangleCliques(perFace[f], scratch, found[thread]);
  };
  runOnWorkerThreads(threads, work);
  Cliques cliques;
  for (Cliques& c : found) cliques.merge(c);
  h.tangentialCliques.assign(cliques.begin(), cliques.end());
  h.tangentialPairs = pairsOfCliques(h.tangentialCliques, int(h.arcs.size()));
}

}  // namespace fcql
