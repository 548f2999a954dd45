#include "tree/node_order.hpp"

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

constexpr int kBits = 11;
constexpr int kPasses = (64 + kBits - 1) / kBits;
constexpr std::size_t kBuckets = std::size_t{1} << kBits;

} // namespace

std::vector<int64_t> ascending_order(std::span<const double> values) {
  const std::size_t n = values.size();
  UninitializedVector<Item> a, b;
  a.resize(n);
  b.resize(n);
  // All digit histograms in one pass.
  std::vector<std::array<std::size_t, kBuckets>> count(kPasses);
  for (auto &c : count)
    c.fill(0);
  for (std::size_t i = 0; i < n; ++i) {
    const uint64_t k = order_key(values[i]);
    a[i] = {k, static_cast<int64_t>(i)};
    for (int p = 0; p < kPasses; ++p)
      ++count[p][(k >> (p * kBits)) & (kBuckets - 1)];
  }
  // Least significant digit first; each pass is stable, so equal keys stay in id order. A digit
  // that all keys share needs no pass.
  for (int p = 0; p < kPasses; ++p) {
    auto &c = count[p];
    if (std::find(c.begin(), c.end(), n) != c.end())
      continue;
    std::size_t sum = 0;
    for (std::size_t &x : c) {
      const std::size_t here = x;
      x = sum;
      sum += here;
    }
    const int shift = p * kBits;
    for (std::size_t i = 0; i < n; ++i)
      b[c[(a[i].key >> shift) & (kBuckets - 1)]++] = a[i];
    a.swap(b);
  }
  std::vector<int64_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
    order[i] = a[i].id;
  return order;
}

} // namespace hoct
