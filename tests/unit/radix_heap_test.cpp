#include "util/radix_heap.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <queue>
#include <random>

using namespace fcql;

namespace {

/// Dijkstra-like use: keys pushed are never below the last one popped. Each node's best key
/// is tracked; the heap must pop every node once, in order of its final key.
/// With `beside`, the heap keeps each node's position in a record of the caller's, next to
/// other data, instead of in its own array.
void checkAgainstSortedOrder(bool beside, std::uint32_t seed) {
  std::mt19937 rng(seed);
  const int n = 3000;
  std::vector<float> best(n, std::numeric_limits<float>::infinity());
  std::vector<char> popped(n, 0);
  RadixHeap heap;
  struct Record {
    float other;
    int position;
  };
  std::vector<Record> records(n, Record{-1.0f, -7});
  if (beside) heap.keepPositionsAt(&records[0].position, sizeof(Record) / sizeof(int));
  else heap.resize(n);
  std::uniform_int_distribution<int> node(0, n - 1);
  std::uniform_real_distribution<float> step(0.0f, 5.0f);
  auto offer = [&](int v, float key) {
    if (popped[v] || !(key < best[v])) return;
    if (std::isinf(best[v])) heap.push({key, v});
    else heap.decrease(best[v], {key, v});
    best[v] = key;
  };
  for (int i = 0; i < 20; ++i) offer(node(rng), step(rng));
  float last = 0;
  int pops = 0, decreases = 0;
  while (!heap.empty()) {
    const auto [key, v] = heap.pop();
    ASSERT_GE(key, last) << "keys must come out in order";
    last = key;
    ASSERT_FALSE(popped[v]) << "node " << v << " popped twice";
    ASSERT_EQ(key, best[v]) << "node " << v << " popped with a key it no longer has";
    popped[v] = 1;
    ++pops;
    // New keys at or above the last one popped, some lowering a pending node's key, some
    // equal to it (ties come out in a fixed order).
    for (int k = std::uniform_int_distribution<int>(0, 3)(rng); k > 0; --k) {
      const int u = node(rng);
      const float newKey = k == 1 ? key : key + step(rng);
      decreases += !std::isinf(best[u]) && !popped[u] && newKey < best[u];
      offer(u, newKey);
    }
  }
  for (int v = 0; v < n; ++v) EXPECT_EQ(bool(popped[v]), !std::isinf(best[v])) << "node " << v;
  EXPECT_GT(pops, n / 2);
  EXPECT_GT(decreases, 50);
  for (const Record& r : records) ASSERT_EQ(r.other, -1.0f) << "the heap wrote outside the positions";
}

}  // namespace

TEST(RadixHeap, PopsInKeyOrderWithDecreasedKeys) {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) checkAgainstSortedOrder(false, seed);
}

TEST(RadixHeap, KeepsPositionsBesideTheCallersData) {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) checkAgainstSortedOrder(true, seed);
}
