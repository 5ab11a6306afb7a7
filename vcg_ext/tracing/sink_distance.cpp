#include "tracing/sink_distance.h"

#include "mesh/worker_threads.h"
#include "tracing/radix_heap.h"

#include <atomic>
#include <limits>
#include <memory>

namespace fcql {

std::vector<float> distancesToNearestTarget(const std::vector<std::uint32_t>& begin, const std::vector<WeightedArc>& arcs,
                                            const std::vector<int>& targets, int threads) {
  const int n = int(begin.size()) - 1;
  // The reversed graph in compressed rows: for each node, the arcs that end there.
  std::vector<std::uint32_t> inBegin(n + 1, 0);
  for (const WeightedArc& a : arcs)
    if (a.target >= 0) ++inBegin[a.target + 1];
  for (int v = 0; v < n; ++v) inBegin[v + 1] += inBegin[v];
  std::vector<WeightedArc> in(inBegin[n]);
  {
    std::vector<std::uint32_t> fill(inBegin.begin(), inBegin.end() - 1);
    for (int u = 0; u < n; ++u)
      for (std::uint32_t i = begin[u]; i < begin[u + 1]; ++i)
        if (arcs[i].target >= 0) in[fill[arcs[i].target]++] = {u, arcs[i].weight};
  }

  // One search per thread, each from its share of the targets, each with its own distances,
  // kept side by side per node: dist[v · T + t]. A search neither records nor settles a
  // distance at a node where another search already holds a shorter one (or an equal one, when
  // that search comes first): what it would find beyond that node the other search finds as
  // well, no longer, so each search covers about the part of the graph nearest its own
  // targets. Other searches' distances are read as they go; such a value only ever falls
  // towards its final one, so a stale read drops a node less often, never wrongly: the first
  // search to reach a node's smallest distance records and settles it. Hence the minimum over
  // the searches is the distance to the nearest target, the same number whatever the timing.
  const int numSearches = workerThreadCount(threads, int(targets.size()));
  const int T = numSearches;
  std::unique_ptr<std::atomic<float>[]> dist(new std::atomic<float>[std::size_t(n) * T]);
  for (std::size_t i = 0; i < std::size_t(n) * T; ++i) dist[i].store(std::numeric_limits<float>::infinity(), std::memory_order_relaxed);
  // Whether another search holds distance d or less at the node whose distances start at `at`.
  auto heldElsewhere = [T](const std::atomic<float>* at, int t, float d) {
    for (int s = 0; s < T; ++s) {
      const float other = at[s].load(std::memory_order_relaxed);
      if (s < t ? other <= d : (s > t && other < d)) return true;
    }
    return false;
  };
  runOnWorkerThreads(numSearches, [&](int t) {
    RadixHeap heap;
    const std::size_t firstTarget = targets.size() * t / T, lastTarget = targets.size() * (t + 1) / T;
    for (std::size_t i = firstTarget; i < lastTarget; ++i) {
      std::atomic<float>& d = dist[std::size_t(targets[i]) * T + t];
      if (d.load(std::memory_order_relaxed) == 0) continue;
      d.store(0, std::memory_order_relaxed);
      heap.pushUntracked({0.0f, targets[i]});
    }
    while (!heap.empty()) {
      const auto [d, v] = heap.pop();
      std::atomic<float>* at = &dist[std::size_t(v) * T];
      // A stale entry (a shorter distance was pushed later), or a node another search holds.
      if (d > at[t].load(std::memory_order_relaxed) || heldElsewhere(at, t, d)) continue;
      const std::uint32_t first = inBegin[v], last = inBegin[v + 1];
      for (std::uint32_t i = first; i < last; ++i) __builtin_prefetch(&dist[std::size_t(in[i].target) * T]);
      for (std::uint32_t i = first; i < last; ++i) {
        const int u = in[i].target;
        const float nd = d + in[i].weight;
        std::atomic<float>& du = dist[std::size_t(u) * T + t];
        if (nd < du.load(std::memory_order_relaxed) && !heldElsewhere(&dist[std::size_t(u) * T], t, nd)) {
          du.store(nd, std::memory_order_relaxed);
          heap.pushUntracked({nd, u});
          __builtin_prefetch(&inBegin[u]);
        }
      }
    }
  });
  std::vector<float> nearest(n);
  for (int v = 0; v < n; ++v) {
    float best = std::numeric_limits<float>::infinity();
    for (int t = 0; t < T; ++t) best = std::min(best, dist[std::size_t(v) * T + t].load(std::memory_order_relaxed));
    nearest[v] = best;
  }
  return nearest;
}

}  // namespace fcql
