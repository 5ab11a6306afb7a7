// Distances to the nearest sink in graph G, which searches for sinks use as a potential.
//
// A search from a port stops at the k nearest sinks; plain Dijkstra settles every node closer
// to the port than the k-th sink, though most of them lie on no short path to any sink. With
// h(n) the length of the shortest path from n to any sink, the reduced weights
//     w'(u, v) = w(u, v) + h(v) − h(u)
// are non-negative (h is a shortest-path distance), a path's reduced length differs from its
// length by h(end) − h(start) only, so Dijkstra on w' settles the sinks in the same order with
// the same shortest paths (A* with the exact distance to the nearest sink as its heuristic),
// while nodes that lead to sinks only the long way round are reached late or never. Nodes
// from which no sink can be reached (h infinite) are left out of such searches altogether.
#pragma once

#include <cstdint>
#include <vector>

namespace fcql {

/// One arc of a graph in compressed rows: `target` (complemented, ~node, for an arc a search
/// for targets need not follow) and its non-negative weight.
struct WeightedArc {
  int target;
  float weight;
};

/// For every node of the graph whose arcs out of node n are arcs[begin[n] .. begin[n + 1]),
/// the length of its shortest path to any node of `targets` (+infinity where none is
/// reachable): Dijkstra searches on the reversed graph, one per thread (0: all hardware
/// threads), each from its share of the targets at once. Arcs with a complemented target are
/// not followed. The result does not depend on the number of threads.
std::vector<float> distancesToNearestTarget(const std::vector<std::uint32_t>& begin, const std::vector<WeightedArc>& arcs,
                                            const std::vector<int>& targets, int threads = 0);

namespace detail {
/// The same searches, run on the calling thread a few steps at a time in an order drawn from
/// `seed`: every way they can overtake each other, made repeatable, for tests.
std::vector<float> distancesToNearestTargetInterleaved(const std::vector<std::uint32_t>& begin,
                                                       const std::vector<WeightedArc>& arcs,
                                                       const std::vector<int>& targets, int searches,
                                                       std::uint32_t seed);
}  // namespace detail

}  // namespace fcql
