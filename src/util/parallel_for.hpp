// A minimal parallel loop over [0, n) in contiguous chunks on the process's worker threads
// (util/worker_pool.hpp). Work items must be independent and write only their own slots: results
// are then identical for any thread count.
#pragma once

#include "util/worker_pool.hpp"

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

// Calls body(chunk, begin, end, worker) for each of `chunks` contiguous chunks of [0, n)
// (chunk k is [n k / chunks, n (k + 1) / chunks)) on `threads` threads; rethrows the first
// exception. Results written per chunk and combined in chunk order do not depend on the thread
// count. Thread t takes the chunks of its own share (the t-th of `threads` runs of consecutive
// chunks) in order, then helps with the other shares' remaining chunks: each thread works on
// one contiguous part of the data in loop after loop (with chunks taken in turn, it would meet
// other parts of the data in each loop than its caches hold from the last), and a thread that
// starts late or meets costlier items is still helped.
template <class Body>
void parallel_chunks(int64_t n, int64_t chunks, int threads, const Body &body) {
  chunks = std::max<int64_t>(chunks, 1);
  threads = static_cast<int>(std::min<int64_t>(std::max(1, threads), chunks));
  if (threads <= 1) {
    for (int64_t c = 0; c < chunks; ++c)
      body(c, n * c / chunks, n * (c + 1) / chunks, 0);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  // Each share's next chunk, on a cache line of its own.
  struct alignas(64) Share {
    std::atomic<int64_t> next;
    int64_t end;
  };
  std::vector<Share> shares(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) {
    shares[t].next.store(chunks * t / threads, std::memory_order_relaxed);
    shares[t].end = chunks * (t + 1) / threads;
  }
  auto work = [&](int t) {
    try {
      for (int i = 0; i < threads; ++i) {
        Share &share = shares[static_cast<std::size_t>((t + i) % threads)];
        for (int64_t c; (c = share.next.fetch_add(1, std::memory_order_relaxed)) < share.end;)
          body(c, n * c / chunks, n * (c + 1) / chunks, t);
      }
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  // The calling thread is worker 0; the others are the process's kept workers.
  run_on_workers(threads, work);
  for (auto &e : errors)
    if (e)
      std::rethrow_exception(e);
}

// Calls body(begin, end, worker) on disjoint chunks of [0, n); rethrows the first exception.
template <class Body> void parallel_for(int64_t n, int threads, const Body &body) {
  threads = static_cast<int>(std::min<int64_t>(std::max(1, threads), std::max<int64_t>(n, 1)));
  if (threads <= 1) {
    body(int64_t{0}, n, 0);
    return;
  }
  // More chunks than threads balance uneven cells (degenerate cells cost more).
  parallel_chunks(
      n, std::min<int64_t>(n, int64_t{threads} * 16), threads,
      [&](int64_t, int64_t begin, int64_t end, int worker) { body(begin, end, worker); });
}

// Offsets of n consecutive runs: offsets[0] = 0, offsets[i + 1] = offsets[i] + size(i), for an
// `offsets` of n + 1 slots. Fixed blocks of items are summed on `threads` threads, their starts
// added up in block order, then each block writes its offsets: integer sums, so the same result
// on any thread count.
template <class Offsets, class Size>
void parallel_offsets(int64_t n, int threads, Offsets &offsets, const Size &size) {
  const int64_t blocks = std::clamp<int64_t>(n / 16384, 1, 256);
  const int workers = threads_for(n, threads, 65536);
  std::vector<int64_t> first(static_cast<std::size_t>(blocks) + 1, 0);
  parallel_chunks(n, blocks, workers, [&](int64_t b, int64_t begin, int64_t end, int) {
    int64_t sum = 0;
    for (int64_t i = begin; i < end; ++i)
      sum += size(i);
    first[static_cast<std::size_t>(b) + 1] = sum;
  });
  for (int64_t b = 0; b < blocks; ++b)
    first[static_cast<std::size_t>(b) + 1] += first[static_cast<std::size_t>(b)];
  offsets[0] = 0;
  parallel_chunks(n, blocks, workers, [&](int64_t b, int64_t begin, int64_t end, int) {
    int64_t at = first[static_cast<std::size_t>(b)];
    for (int64_t i = begin; i < end; ++i) {
      at += size(i);
      offsets[i + 1] = at;
    }
  });
}

} // namespace hoct
