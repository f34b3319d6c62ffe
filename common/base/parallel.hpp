/// @file parallel.hpp
/// Runs a loop over image rows on every core: the ray-cast references are the only CPU work that
/// needs it, and each row is independent.
#pragma once
#include <algorithm>
#include <thread>
#include <vector>

namespace wb {

/// Calls body(y) for every y in [0, height), rows interleaved across the machine's cores (or
/// `threadCount` threads, when it is above 0); returns when all are done. `body` must be safe to run
/// on several rows at once.
template <class F>
void forEachRow(int height, F body, int threadCount = 0) {
  const int threads = threadCount > 0 ? threadCount : int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([=] {
      for (int y = t; y < height; y += threads) body(y);
    });
  for (auto& th : pool) th.join();
}

}  // namespace wb
