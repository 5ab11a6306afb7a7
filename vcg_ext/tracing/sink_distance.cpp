#include "tracing/sink_distance.h"

#include "util/worker_threads.h"
#include "util/radix_heap.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <type_traits>

namespace fcql {
namespace {

/// The searches of distancesToNearestTarget: one per share of the targets, each with its own
/// distances, kept side by side per node: dist[v · T + t]. A search neither records nor
/// settles a distance at a node where another search already holds a shorter one (or an equal
/// one, when that search comes first): what it would find beyond that node the other search
/// finds as well, no longer, so each search covers about the part of the graph nearest its own
/// targets. Other searches' distances are read as they go; such a value only ever falls towards
/// its final one, so a stale read drops a node less often, never wrongly: the first search to
/// reach a node's smallest distance records and settles it. Hence the minimum over the
/// searches is the distance to the nearest target, the same number whatever the timing.
class SharedSearches {
public:
  SharedSearches(const std::vector<std::uint32_t>& begin, const std::vector<WeightedArc>& arcs,
                 const std::vector<int>& targets, int searches)
      : n_(int(begin.size()) - 1), T_(searches), targets_(targets), heaps_(searches) {
    // The reversed graph in compressed rows: for each node, the arcs that end there.
    inBegin_.assign(n_ + 1, 0);
    for (const WeightedArc& a : arcs)
      if (a.target >= 0) ++inBegin_[a.target + 1];
    for (int v = 0; v < n_; ++v) inBegin_[v + 1] += inBegin_[v];
    in_.resize(inBegin_[n_]);
    std::vector<std::uint32_t> fill(inBegin_.begin(), inBegin_.end() - 1);
    for (int u = 0; u < n_; ++u)
      for (std::uint32_t i = begin[u]; i < begin[u + 1]; ++i)
        if (arcs[i].target >= 0) in_[fill[arcs[i].target]++] = {u, arcs[i].weight};
    dist_.reset(new Slot[std::size_t(n_) * T_]);
    for (std::size_t i = 0; i < std::size_t(n_) * T_; ++i)
      dist_[i].dist.store(std::numeric_limits<float>::infinity(), std::memory_order_relaxed);
    for (int t = 0; t < T_; ++t) heaps_[t].keepPositionsAt(&dist_[t].position, T_ * sizeof(Slot) / sizeof(int));
  }

  int searches() const { return T_; }

  /// Search t's targets enter its heap.
  void start(int t) {
    const std::size_t first = targets_.size() * t / T_, last = targets_.size() * (t + 1) / T_;
    for (std::size_t i = first; i < last; ++i) {
      std::atomic<float>& d = distance(targets_[i], t);
      if (d.load(std::memory_order_relaxed) == 0) continue;
      d.store(0, std::memory_order_relaxed);
      heaps_[t].push({0.0f, targets_[i]});
    }
  }

  /// Search t pops one entry and, unless another search holds its node, relaxes
  /// the arcs into it. False once search t is done.
  bool step(int t) {
    RadixHeap& heap = heaps_[t];
    if (heap.empty()) return false;
    const auto [d, v] = heap.pop();
    if (heldElsewhere(v, t, d)) return true;
    const std::uint32_t first = inBegin_[v], last = inBegin_[v + 1];
    for (std::uint32_t i = first; i < last; ++i) __builtin_prefetch(&distance(in_[i].target, 0));
    for (std::uint32_t i = first; i < last; ++i) {
      const int u = in_[i].target;
      const float nd = d + in_[i].weight;
      std::atomic<float>& du = distance(u, t);
      const float old = du.load(std::memory_order_relaxed);
      if (nd < old && !heldElsewhere(u, t, nd)) {
        du.store(nd, std::memory_order_relaxed);
        if (std::isinf(old)) heap.push({nd, u});
        else heap.decrease(old, {nd, u});
        __builtin_prefetch(&inBegin_[u]);
      }
    }
    return true;
  }

  /// The minimum over the searches, once all are done.
  std::vector<float> nearest() const {
    std::vector<float> out(n_);
    for (int v = 0; v < n_; ++v) {
      float best = std::numeric_limits<float>::infinity();
      for (int t = 0; t < T_; ++t) best = std::min(best, dist_[std::size_t(v) * T_ + t].dist.load(std::memory_order_relaxed));
      out[v] = best;
    }
    return out;
  }

private:
  std::atomic<float>& distance(int v, int t) const { return dist_[std::size_t(v) * T_ + t].dist; }

  /// Whether another search holds distance d or less at node v (d itself, if it comes first).
  bool heldElsewhere(int v, int t, float d) const {
    for (int s = 0; s < T_; ++s) {
      const float other = distance(v, s).load(std::memory_order_relaxed);
      if (s < t ? other <= d : (s > t && other < d)) return true;
    }
    return false;
  }

  int n_, T_;
  const std::vector<int>& targets_;
  std::vector<std::uint32_t> inBegin_;
  std::vector<WeightedArc> in_;
  /// Search t's distance at a node, and the node's position in search t's heap beside it
  /// (the heap notes it just after the distance is written: no cache miss of its own).
  struct Slot {
    std::atomic<float> dist;
    int position;
  };
  static_assert(std::is_standard_layout<Slot>::value && sizeof(Slot) % sizeof(int) == 0,
                "the heaps address positions as ints, a whole number of them per slot");
  std::unique_ptr<Slot[]> dist_;
  std::vector<RadixHeap> heaps_;
};

}  // namespace

std::vector<float> distancesToNearestTarget(const std::vector<std::uint32_t>& begin, const std::vector<WeightedArc>& arcs,
                                            const std::vector<int>& targets, int threads) {
  SharedSearches searches(begin, arcs, targets, workerThreadCount(threads, int(targets.size())));
  runOnWorkerThreads(searches.searches(), [&](int t) {
    searches.start(t);
    while (searches.step(t)) {
    }
  });
  return searches.nearest();
}

namespace detail {

std::vector<float> distancesToNearestTargetInterleaved(const std::vector<std::uint32_t>& begin,
                                                       const std::vector<WeightedArc>& arcs,
                                                       const std::vector<int>& targets, int searches,
                                                       std::uint32_t seed) {
  SharedSearches shared(begin, arcs, targets, std::max(1, searches));
  std::vector<int> running;
  for (int t = 0; t < shared.searches(); ++t) shared.start(t), running.push_back(t);
  std::mt19937 rng(seed);
  while (!running.empty()) {
    // A few steps of one search at a time, so that searches overtake each other.
    const std::size_t pick = std::uniform_int_distribution<std::size_t>(0, running.size() - 1)(rng);
    const int burst = std::uniform_int_distribution<int>(1, 8)(rng);
    for (int i = 0; i < burst; ++i)
      if (!shared.step(running[pick])) {
        running.erase(running.begin() + pick);
        break;
      }
  }
  return shared.nearest();
}

}  // namespace detail
}  // namespace fcql
