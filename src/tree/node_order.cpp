#include "tree/node_order.hpp"

#include "util/uninitialized_vector.hpp"

#include <algorithm>
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

// Sorts a[0, n) by (key, id), with scratch b of the same size: small ranges by comparison, large
// ones partitioned (stably) on the 12 highest bits in which their keys differ, each part then
// sorted the same way. Floating-point keys share their leading (exponent) bits in clusters, so a
// fixed digit would leave most keys in a few buckets; this adapts to every range's own prefix.
void sort_items(Item *a, Item *b, std::size_t n) {
  if (n <= 2048) {
    std::sort(a, a + n, item_less);
    return;
  }
  uint64_t lo = a[0].key, hi = a[0].key;
  for (std::size_t i = 1; i < n; ++i) {
    lo = std::min(lo, a[i].key);
    hi = std::max(hi, a[i].key);
  }
  if (lo == hi)
    return; // equal keys, still in id order (every partition is stable, the input is by id)
  constexpr int kBits = 12;
  constexpr std::size_t kBuckets = std::size_t{1} << kBits;
  const int shift = std::max(64 - std::countl_zero(hi ^ lo) - kBits, 0);
  const uint64_t base = lo >> shift;
  std::vector<std::size_t> start(kBuckets + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    ++start[(a[i].key >> shift) - base + 1];
  for (std::size_t k = 1; k <= kBuckets; ++k)
    start[k] += start[k - 1];
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    b[fill[(a[i].key >> shift) - base]++] = a[i];
  std::copy(b, b + n, a);
  for (std::size_t k = 0; k < kBuckets; ++k)
    if (start[k + 1] - start[k] > 1)
      sort_items(a + start[k], b + start[k], start[k + 1] - start[k]);
}

} // namespace

std::vector<int64_t> ascending_order(std::span<const double> values) {
  const std::size_t n = values.size();
  UninitializedVector<Item> a, b;
  a.resize(n);
  b.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    a[i] = {order_key(values[i]), static_cast<int64_t>(i)};
  sort_items(a.data(), b.data(), n);
  std::vector<int64_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
    order[i] = a[i].id;
  return order;
}

} // namespace hoct
