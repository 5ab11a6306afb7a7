// Worker threads for the library's parallel loops (graph G's arcs, the searches from the ports,
// graph H's crossings): how many to start, and running one function on each of them.
#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace fcql {

/// Threads for `requested` (0 or less: all hardware threads), at most `useful` (the number of
/// work items), at least 1.
inline int workerThreadCount(int requested, int useful) {
  int threads = requested > 0 ? requested : int(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(threads, useful));
}

/// Runs work(t) for t = 0 .. threads−1, work(0) on the calling thread, and returns when all
/// have finished.
template <class Work>
void runOnWorkerThreads(int threads, Work&& work) {
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back([&work, t] { work(t); });
  work(0);
  for (auto& th : pool) th.join();
}

}  // namespace fcql
