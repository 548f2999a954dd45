#include "tree/scalar_graph.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace hoct {

ScalarGraph::ScalarGraph(std::vector<double> values,
                         const std::vector<std::pair<int64_t, int64_t>> &edges)
    : values_(std::move(values)) {
  const int64_t n = static_cast<int64_t>(values_.size());
  std::vector<std::pair<int64_t, int64_t>> e;
  e.reserve(edges.size());
  for (auto [a, b] : edges) {
    if (a < 0 || b < 0 || a >= n || b >= n)
      throw std::out_of_range("ScalarGraph: edge endpoint out of range");
    if (a != b)
      e.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  offset_.assign(n + 1, 0);
  for (auto [a, b] : e) {
    ++offset_[a + 1];
    ++offset_[b + 1];
  }
  std::partial_sum(offset_.begin(), offset_.end(), offset_.begin());
  adj_.resize(offset_[n]);
  std::vector<int64_t> fill(offset_.begin(), offset_.end() - 1);
  for (auto [a, b] : e) {
    adj_[fill[a]++] = b;
    adj_[fill[b]++] = a;
  }
  ascending_.resize(n);
  std::iota(ascending_.begin(), ascending_.end(), int64_t{0});
  std::sort(ascending_.begin(), ascending_.end(), [&](int64_t a, int64_t b) { return less(a, b); });
}

} // namespace hoct
