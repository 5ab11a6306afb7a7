#include "tracing/sink_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>

using namespace fcql;

namespace {

struct Csr {
  std::vector<std::uint32_t> begin;
  std::vector<WeightedArc> arcs;
};

/// A random graph whose nodes are points on a line: arcs go to nodes nearby, weighted at
/// least by how far apart the points are, so that shortest paths are long chains and many
/// nodes are reached by several paths of nearly equal length; a few arcs are complemented.
/// With `whole` weights, they are small whole numbers, zero included: many exact ties.
Csr randomGraph(int n, std::mt19937& rng, bool whole = false) {
  Csr g;
  g.begin.push_back(0);
  std::uniform_int_distribution<int> degree(0, 5), step(-12, 12), skip(0, 19), small(0, 3);
  std::uniform_real_distribution<float> extra(0.0f, 1.5f);
  for (int u = 0; u < n; ++u) {
    for (int k = degree(rng); k > 0; --k) {
      const int v = std::clamp(u + step(rng), 0, n - 1);
      if (v == u) continue;
      const float w = whole ? float(small(rng)) : float(std::abs(v - u)) * (1.0f + extra(rng));
      g.arcs.push_back({skip(rng) == 0 ? ~v : v, w});
    }
    g.begin.push_back(std::uint32_t(g.arcs.size()));
  }
  return g;
}

/// The textbook answer: Dijkstra from every target at once on the reversed graph.
std::vector<float> reference(const Csr& g, const std::vector<int>& targets) {
  const int n = int(g.begin.size()) - 1;
  std::vector<std::vector<std::pair<int, float>>> in(n);
  for (int u = 0; u < n; ++u)
    for (std::uint32_t i = g.begin[u]; i < g.begin[u + 1]; ++i)
      if (g.arcs[i].target >= 0) in[g.arcs[i].target].push_back({u, g.arcs[i].weight});
  std::vector<float> dist(n, std::numeric_limits<float>::infinity());
  std::priority_queue<std::pair<float, int>, std::vector<std::pair<float, int>>, std::greater<>> queue;
  for (int t : targets) dist[t] = 0, queue.push({0.0f, t});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (const auto& [u, w] : in[v])
      if (d + w < dist[u]) dist[u] = d + w, queue.push({dist[u], u});
  }
  return dist;
}

}  // namespace

TEST(SinkDistance, MatchesDijkstraFromAllTargetsWhateverTheThreads) {
  // Each search drops what another holds more cheaply, reading the others' distances while
  // they change; the minimum must still be the exact distance, bit for bit, on any number of
  // searches, with targets shared out in any order.
  std::mt19937 rng(7);
  long unreachable = 0;
  for (int round = 0; round < 20; ++round) {
    const int n = 3000 + 500 * round;
    const Csr g = randomGraph(n, rng);
    std::vector<int> targets;
    std::uniform_int_distribution<int> node(0, n - 1);
    for (int k = 0; k < 2 + round; ++k) targets.push_back(node(rng));
    const std::vector<float> want = reference(g, targets);
    for (int threads : {1, 2, 3, 5}) {
      const std::vector<float> got = distancesToNearestTarget(g.begin, g.arcs, targets, threads);
      ASSERT_EQ(got.size(), want.size());
      for (int v = 0; v < n; ++v)
        ASSERT_EQ(got[v], want[v]) << "node " << v << " of round " << round << " on " << threads << " threads";
    }
    for (float d : want) unreachable += std::isinf(d);
  }
  EXPECT_GT(unreachable, 0) << "no node without a way to a target: the infinite case goes untested";
}

TEST(SinkDistance, SearchesOvertakingEachOtherInAnyOrderGiveTheExactDistances) {
  // The searches share nodes by reading each other's distances as they change. Threads on
  // two cores barely overlap on small graphs, so here they run a few steps at a time in
  // drawn orders, overtaking each other every way, on graphs full of exact ties (whole
  // weights, zeros among them). What steps cannot show is two searches checking and storing
  // the same node at the same instant; the tie rule (the first search keeps an equal
  // distance) is what makes that safe, and only its argument covers it.
  std::mt19937 rng(11);
  long ties = 0;
  for (int round = 0; round < 12; ++round) {
    const int n = 400 + 300 * round;
    const Csr g = randomGraph(n, rng, /*whole=*/true);
    std::vector<int> targets;
    std::uniform_int_distribution<int> node(0, n - 1);
    for (int k = 0; k < 3 + 2 * round; ++k) targets.push_back(node(rng));
    const std::vector<float> want = reference(g, targets);
    for (int searches : {2, 3, 4})
      for (std::uint32_t seed = 0; seed < 6; ++seed) {
        const std::vector<float> got = detail::distancesToNearestTargetInterleaved(g.begin, g.arcs, targets, searches, seed);
        for (int v = 0; v < n; ++v)
          ASSERT_EQ(got[v], want[v]) << "node " << v << ", round " << round << ", " << searches << " searches, order " << seed;
      }
    for (int u = 0; u < n; ++u)
      for (std::uint32_t i = g.begin[u]; i < g.begin[u + 1]; ++i)
        ties += g.arcs[i].target >= 0 && want[u] == g.arcs[i].weight + want[g.arcs[i].target] && g.arcs[i].weight == 0;
  }
  EXPECT_GT(ties, 100) << "too few zero-weight arcs on shortest paths to exercise ties";
}

TEST(SinkDistance, AnArcWithoutALengthLeadsNowhere) {
  // A NaN weight (a broken move) must not become a free way to a target: the distances are
  // those of the graph without that arc.
  std::mt19937 rng(5);
  Csr g = randomGraph(2000, rng);
  Csr without = g;
  long broken = 0;
  for (std::size_t i = 0; i < g.arcs.size(); i += 7)
    if (g.arcs[i].target >= 0) {
      g.arcs[i].weight = std::numeric_limits<float>::quiet_NaN();
      without.arcs[i].target = ~without.arcs[i].target;
      ++broken;
    }
  ASSERT_GT(broken, 100);
  const std::vector<int> targets = {5, 700, 1500};
  const std::vector<float> want = reference(without, targets);
  for (int threads : {1, 2}) {
    const std::vector<float> got = distancesToNearestTarget(g.begin, g.arcs, targets, threads);
    for (std::size_t v = 0; v < want.size(); ++v) ASSERT_EQ(got[v], want[v]) << "node " << v << " on " << threads << " threads";
  }
}

TEST(SinkDistance, NoTargetsLeaveEveryNodeUnreachable) {
  std::mt19937 rng(3);
  const Csr g = randomGraph(200, rng);
  for (float d : distancesToNearestTarget(g.begin, g.arcs, {}, 2)) EXPECT_TRUE(std::isinf(d));
}
