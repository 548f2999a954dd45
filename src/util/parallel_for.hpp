// A minimal parallel loop over [0, n) in contiguous chunks with std::threads. Work items must be
// independent and write only their own slots: results are then identical for any thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

namespace hoct {

// Number of threads to use for `requested` (0 = all hardware threads).
inline int thread_count(int requested) {
  if (requested > 0)
    return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

// At most `threads`, and few enough that each gets at least `grain` of the n items (starting a
// thread for less work costs more than it saves).
inline int threads_for(int64_t n, int threads, int64_t grain) {
  const int64_t useful = std::max<int64_t>(1, n / std::max<int64_t>(grain, 1));
  return static_cast<int>(std::min<int64_t>(std::max(1, threads), useful));
}

// Calls body(begin, end, worker) on disjoint chunks of [0, n); rethrows the first exception.
template <class Body> void parallel_for(int64_t n, int threads, const Body &body) {
  threads = static_cast<int>(std::min<int64_t>(std::max(1, threads), std::max<int64_t>(n, 1)));
  if (threads <= 1) {
    body(int64_t{0}, n, 0);
    return;
  }
  // More chunks than threads balance uneven cells (degenerate cells cost more).
  const int64_t chunks = std::min<int64_t>(n, int64_t{threads} * 16);
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  std::atomic<int64_t> next{0};
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      try {
        for (int64_t c; (c = next.fetch_add(1)) < chunks;)
          body(n * c / chunks, n * (c + 1) / chunks, t);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  for (auto &th : pool)
    th.join();
  for (auto &e : errors)
    if (e)
      std::rethrow_exception(e);
}

} // namespace hoct
