// A monotone priority queue of (distance, node) for Dijkstra's searches in graph G.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace fcql {

/// A radix heap (Ahuja, Mehlhorn, Orlin, Tarjan 1990) of (distance, node): a monotone
/// priority queue, which is all Dijkstra needs (no key pushed is below the last one popped).
/// Non-negative floats order like their bit patterns, so keys are those bits; an entry lives
/// in the bucket of the highest bit in which its key differs from the last key popped. Pushes
/// are O(1) and each entry moves down at most 32 times, without the branchy sift-downs of a
/// comparison heap. Among equal keys the order is fixed (last in, first out), so results do
/// not depend on timing. A node is in the heap at most once: a shorter distance found for it
/// moves its entry (decrease), found through the position kept per node, instead of adding a
/// second one that would be popped stale later (half of all pops, in graph G's searches).
/// The positions live in the heap (resize()) or beside the caller's own data of each node
/// (keepPositionsAt()), one of which must come before the first push.
class RadixHeap {
public:
  using Entry = std::pair<float, int>;
  bool empty() const { return size_ == 0; }
  void clear() {
    for (auto& b : buckets_) b.clear();
    size_ = 0;
    last_ = 0;
  }
  void push(Entry e) {
    place({keyOf(e.first), e.second});
    ++size_;
  }
  /// Lowers the key of `node`, in the heap with key `old`, to `e.first`.
  void decrease(float old, Entry e) {
    auto& b = buckets_[bucketOf(keyOf(old))];
    const int at = position(e.second);
    b[at] = b.back();
    if (b[at].node >= 0) position(b[at].node) = at;
    b.pop_back();
    --size_;
    push(e);
  }
  /// Room in the heap for the positions of nodes 0 .. nodes − 1 (terminals, negative, are
  /// never moved).
  void resize(std::size_t nodes) {
    position_.resize(nodes);
    positionBase_ = position_.data();
    positionStride_ = 1;
  }
  /// Keeps node n's position at base[n · stride] instead: beside data of the node's that the
  /// caller touches just before pushing or moving it, so that noting the position costs no
  /// cache miss of its own.
  void keepPositionsAt(int* base, std::size_t stride) {
    position_.clear();
    positionBase_ = base;
    positionStride_ = stride;
  }
  /// Removes and returns an entry with the smallest key. Requires !empty().
  Entry pop() {
    if (buckets_[0].empty()) {
      int i = 1;
      while (buckets_[i].empty()) ++i;
      std::uint32_t smallest = buckets_[i][0].key;
      for (const Item& it : buckets_[i]) smallest = std::min(smallest, it.key);
      last_ = smallest;
      for (const Item& it : buckets_[i]) place(it);
      buckets_[i].clear();
    }
    Item it = buckets_[0].back();
    buckets_[0].pop_back();
    --size_;
    float d;
    std::memcpy(&d, &it.key, sizeof d);
    return {d, it.node};
  }

private:
  struct Item {
    std::uint32_t key;
    int node;
  };
  static std::uint32_t keyOf(float d) {
    std::uint32_t k;
    std::memcpy(&k, &d, sizeof k);
    return k;
  }
  int bucketOf(std::uint32_t key) const { return key == last_ ? 0 : 32 - __builtin_clz(key ^ last_); }
  int& position(int node) { return positionBase_[std::size_t(node) * positionStride_]; }
  /// Appends the item to its bucket, noting where a node went.
  void place(const Item& it) {
    auto& b = buckets_[bucketOf(it.key)];
    if (it.node >= 0) position(it.node) = int(b.size());
    b.push_back(it);
  }

  std::array<std::vector<Item>, 33> buckets_;
  std::vector<int> position_;  ///< per node: its index in its bucket while in the heap
  int* positionBase_ = nullptr;
  std::size_t positionStride_ = 1;
  std::size_t size_ = 0;
  std::uint32_t last_ = 0;
};

}  // namespace fcql
