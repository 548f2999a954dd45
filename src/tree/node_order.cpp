#include "tree/node_order.hpp"

#include "util/parallel_for.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

namespace hoct {
namespace {

// Unsigned keys in the order of the doubles: negative numbers flipped whole, positive ones with
// the sign bit set. -0 is mapped as +0, so that the two tie (and fall back to id order).
uint64_t order_key(double x) {
  if (x == 0)
    x = 0.0;
  const uint64_t u = std::bit_cast<uint64_t>(x);
  return (u >> 63) ? ~u : (u | (uint64_t{1} << 63));
}

struct Item {
  uint64_t key;
  int64_t id;
};

bool item_less(const Item &a, const Item &b) {
  return a.key < b.key || (a.key == b.key && a.id < b.id);
}

// Sorts a[0, n) by (key, id) into a (to_b false) or b (to_b true), using the other array as
// scratch: small ranges by comparison, larger ones partitioned (stably, from one array into the
// other) on the highest bits in which their keys differ, up to 11 bits (16 for a million keys
// and more) and fewer for smaller ranges (about 8 keys per part), each part then sorted the same
// way with the arrays' roles swapped. Floating-point keys share their leading (exponent) bits in
// clusters, so a fixed digit would leave most keys in a few buckets; this adapts to every range's
// own prefix. With threads > 1 the parts of the first partition are sorted on that many threads
// (each part as on one; the result is the same).
void sort_items(Item *a, Item *b, std::size_t n, bool to_b, int threads = 1) {
  if (n <= 48) {
    std::sort(a, a + n, item_less);
    if (to_b)
      std::copy(a, a + n, b);
    return;
  }
  uint64_t lo = a[0].key, hi = a[0].key;
  for (std::size_t i = 1; i < n; ++i) {
    lo = std::min(lo, a[i].key);
    hi = std::max(hi, a[i].key);
  }
  if (lo == hi) {
    // Equal keys, still in id order (every partition is stable, the input is by id).
    if (to_b)
      std::copy(a, a + n, b);
    return;
  }
  // Ranges of a million keys and more: up to 16 bits (the counters on the heap). Values of one
  // field share their sign and exponent in a few clusters, so a first 11-bit pass leaves most
  // keys in a few parts of a hundred thousand or more and a second pass over memory; 16 bits
  // leave parts that the next pass sorts in cache.
  constexpr int kMaxBits = 11, kMaxTopBits = 16;
  const int max_bits = n >= (std::size_t{1} << 20) ? kMaxTopBits : kMaxBits;
  const int bits = std::clamp(static_cast<int>(std::bit_width(n)) - 3, 3, max_bits);
  const std::size_t buckets = std::size_t{1} << bits;
  const int shift = std::max(64 - std::countl_zero(hi ^ lo) - bits, 0);
  const uint64_t base = lo >> shift;
  auto partition = [&](uint32_t *start, uint32_t *fill) { // n < 2^32 (ascending_order)
    std::fill(start, start + buckets + 1, 0u);
    for (std::size_t i = 0; i < n; ++i)
      ++start[(a[i].key >> shift) - base + 1];
    for (std::size_t k = 1; k <= buckets; ++k)
      start[k] += start[k - 1];
    std::copy(start, start + buckets, fill);
    for (std::size_t i = 0; i < n; ++i)
      b[fill[(a[i].key >> shift) - base]++] = a[i];
    auto sort_parts = [&](std::size_t k0, std::size_t k1) {
      for (std::size_t k = k0; k < k1; ++k)
        if (start[k + 1] > start[k])
          sort_items(b + start[k], a + start[k], start[k + 1] - start[k], !to_b);
    };
    if (threads <= 1) {
      sort_parts(0, buckets);
      return;
    }
    // Runs of consecutive parts of about n / chunks keys each (a part is never split), handed
    // out to the threads in turn.
    const int64_t chunks = int64_t{16} * threads;
    auto first_part = [&](int64_t j) {
      const uint32_t at =
          static_cast<uint32_t>(n * static_cast<std::size_t>(j) / static_cast<std::size_t>(chunks));
      return static_cast<std::size_t>(std::lower_bound(start, start + buckets, at) - start);
    };
    parallel_chunks(chunks, chunks, threads, [&](int64_t j, int64_t, int64_t, int) {
      sort_parts(first_part(j), j + 1 == chunks ? buckets : first_part(j + 1));
    });
  };
  if (bits > kMaxBits) {
    std::vector<uint32_t> start(buckets + 1), fill(buckets);
    partition(start.data(), fill.data());
  } else {
    std::array<uint32_t, (std::size_t{1} << kMaxBits) + 1> start;
    std::array<uint32_t, std::size_t{1} << kMaxBits> fill;
    partition(start.data(), fill.data());
  }
}

} // namespace

std::vector<int64_t> ascending_order(std::span<const double> values, int threads) {
  std::vector<int64_t> order(values.size());
  ascending_order(values, order, threads);
  return order;
}

void ascending_order(std::span<const double> values, std::span<int64_t> order, int threads) {
  const int64_t n = static_cast<int64_t>(values.size());
  threads = threads_for(n, threads, int64_t{1} << 16);
  UninitializedVector<Item> a, b;
  a.resize(static_cast<std::size_t>(n));
  b.resize(static_cast<std::size_t>(n));
  parallel_for(n, threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t i = begin; i < end; ++i)
      a[i] = {order_key(values[i]), i};
  });
  if (n < (int64_t{1} << 32))
    sort_items(a.data(), b.data(), static_cast<std::size_t>(n), false, threads);
  else
    std::sort(a.begin(), a.end(), item_less);
  parallel_for(n, threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t i = begin; i < end; ++i)
      order[i] = a[i].id;
  });
}

} // namespace hoct
