// Disjoint sets that several threads may unite at once, without locks: a root is linked under
// the other, smaller root by compare-and-swap, and finds halve their paths the same way. Every
// link points to a smaller element, so the structure never has a cycle and each set's root is its
// smallest element: the partition and its roots do not depend on the order of the unions, nor on
// the thread count.
#pragma once

#include "util/parallel_for.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <utility>

namespace hoct {

class ConcurrentSets {
public:
  // n singletons, set up on `threads` threads.
  ConcurrentSets(int64_t n, int threads) : parent_(static_cast<std::size_t>(n)) {
    parallel_for(n, threads_for(n, threads, 65536), [&](int64_t begin, int64_t end, int) {
      for (int64_t x = begin; x < end; ++x)
        parent_[x] = x;
    });
  }

  int64_t find(int64_t x) {
    for (;;) {
      int64_t p = link(x).load(std::memory_order_relaxed);
      if (p == x)
        return x;
      const int64_t g = link(p).load(std::memory_order_relaxed);
      if (g != p) // halve: x skips to its grandparent (still an ancestor if x's link moved on)
        link(x).compare_exchange_weak(p, g, std::memory_order_relaxed);
      x = g;
    }
  }

  void unite(int64_t a, int64_t b) {
    for (;;) {
      a = find(a);
      b = find(b);
      if (a == b)
        return;
      if (a < b)
        std::swap(a, b);
      int64_t root = a; // a is linked only if it is still a root
      if (link(a).compare_exchange_strong(root, b, std::memory_order_relaxed))
        return;
    }
  }

  // The number of sets (call when no thread unites any more).
  int64_t count(int threads) {
    const int64_t n = static_cast<int64_t>(parent_.size());
    std::vector<int64_t> roots(static_cast<std::size_t>(std::max(threads, 1)), 0);
    parallel_for(n, threads_for(n, threads, 65536), [&](int64_t begin, int64_t end, int worker) {
      int64_t r = 0;
      for (int64_t x = begin; x < end; ++x)
        r += parent_[x] == x;
      roots[static_cast<std::size_t>(worker)] += r;
    });
    int64_t total = 0;
    for (int64_t r : roots)
      total += r;
    return total;
  }

private:
  std::atomic_ref<int64_t> link(int64_t x) {
    return std::atomic_ref<int64_t>(parent_[static_cast<std::size_t>(x)]);
  }

  UninitializedVector<int64_t> parent_;
};

} // namespace hoct
