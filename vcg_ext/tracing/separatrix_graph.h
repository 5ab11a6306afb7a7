// Graph H of the paper (§3.3): candidate separatrices between ports and how they cross.
//
// One node per port (a source identified with its sink); one arc per source-to-sink path
// found by the searches, with the two opposite paths between the same pair of ports merged
// (the shorter is kept). Two candidates that meet inside a triangle cross orthogonally or
// tangentially, decided combinatorially from the direction classes they follow in that
// triangle (paper Fig. 5): same direction up to a half turn = tangential. The tangential
// crossings are found per triangle as cliques: sets of arcs that pairwise cross there.
#pragma once

#include "tracing/separatrix_tracer.h"

#include <utility>
#include <vector>

namespace fcql {

struct CandidateSeparatrix {
  int portA = -1, portB = -1;  ///< portA = the source the kept path was traced from
  double length = 0;           ///< anisotropic length γ
  TracedPath path;
};

struct SeparatrixGraph {
  std::vector<CandidateSeparatrix> arcs;
  /// Pairs (i < j) of arcs that cross tangentially somewhere (they can't both be selected).
  /// Orthogonal crossings constrain nothing and are not listed.
  std::vector<std::pair<int, int>> tangentialPairs;
  /// Sets of arcs (increasing, at least two, no set repeated) that pairwise cross
  /// tangentially in one triangle; every pair of tangentialPairs is in one of them. The
  /// selection's conflict rows (Eq. 3), much tighter than the pairs.
  std::vector<std::vector<int>> tangentialCliques;
  /// Per port: the arcs incident to it.
  std::vector<std::vector<int>> arcsAtPort;
};

/// Whether the path meets itself tangentially: two of its pieces in one triangle, in one
/// direction class up to a half turn, cross, touch or run along each other.
bool meetsItself(const TracedPath& path);

/// Builds H from the results of the searches (any order; the result does not depend on it).
SeparatrixGraph buildSeparatrixGraph(const GeodesicGraph& graph, const std::vector<std::vector<TracedPath>>& searches);

/// Runs a search from every port (k sinks, no barriers) and builds H.
SeparatrixGraph traceCandidateSeparatrices(const GeodesicGraph& graph, const ProgressCallback& progress = nullptr);

/// Finds the arcs of `h` that meet tangentially (fills tangentialCliques and tangentialPairs),
/// on `threads` threads (0: all hardware threads); the result does not depend on them. Per
/// triangle and direction parity, the distinct chords its pieces follow are covered greedily
/// by cliques of chords that pairwise meet, each holding every arc along its chords.
void classifyCrossings(const SurfaceMesh& mesh, SeparatrixGraph& h, int threads = 0);

}  // namespace fcql
