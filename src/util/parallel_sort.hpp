// Sorting on several threads: contiguous pieces sorted at once, then neighbouring pieces merged
// pairwise (the pairs of a round at once) until one remains. For a strict total order (no two
// distinct elements equivalent) the result is std::sort's, whatever the thread count.
#pragma once

#include "util/parallel_for.hpp"

#include <algorithm>
#include <cstdint>
#include <iterator>

namespace hoct {

template <class It, class Less = std::less<>>
void parallel_sort(It first, It last, int threads, Less less = {}) {
  const int64_t n = static_cast<int64_t>(std::distance(first, last));
  const int64_t pieces = threads_for(n, threads, 1 << 16);
  if (pieces <= 1) {
    std::sort(first, last, less);
    return;
  }
  auto at = [&](int64_t piece) { return first + static_cast<std::ptrdiff_t>(n * piece / pieces); };
  parallel_chunks(pieces, pieces, static_cast<int>(pieces),
                  [&](int64_t p, int64_t, int64_t, int) { std::sort(at(p), at(p + 1), less); });
  for (int64_t width = 1; width < pieces; width *= 2) {
    const int64_t pairs = (pieces + 2 * width - 1) / (2 * width);
    parallel_chunks(pairs, pairs, static_cast<int>(std::min<int64_t>(pairs, threads)),
                    [&](int64_t k, int64_t, int64_t, int) {
                      const int64_t a = 2 * width * k, mid = std::min(a + width, pieces),
                                    b = std::min(a + 2 * width, pieces);
                      if (mid < b)
                        std::inplace_merge(at(a), at(mid), at(b), less);
                    });
  }
}

} // namespace hoct
