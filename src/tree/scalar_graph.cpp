#include "tree/scalar_graph.hpp"

#include "tree/node_order.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace hoct {

ScalarGraph::ScalarGraph(std::vector<double> values, std::span<const GraphEdge> edges)
    : values_(std::move(values)) {
  const int64_t n = static_cast<int64_t>(values_.size());
  // Bucket the edges by their lower endpoint (counting sort, linear), then sort and deduplicate
  // each (small) bucket: no global sort of all edges.
  std::vector<int64_t> start(n + 1, 0);
  for (auto [a, b] : edges) {
    if (a < 0 || b < 0 || a >= n || b >= n)
      throw std::out_of_range("ScalarGraph: edge endpoint out of range");
    if (a != b)
      ++start[std::min(a, b) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int64_t> upper(start[n]), fill(start.begin(), start.end() - 1);
  for (auto [a, b] : edges)
    if (a != b)
      upper[fill[std::min(a, b)]++] = std::max(a, b);
  offset_.assign(n + 1, 0);
  int64_t kept = 0;
  for (int64_t a = 0; a < n; ++a) {
    auto first = upper.begin() + start[a], last = upper.begin() + start[a + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    for (auto it = first; it != last; ++it) {
      upper[kept++] = *it;
      ++offset_[a + 1];
      ++offset_[*it + 1];
    }
    start[a] = kept - (last - first); // the bucket's new start in the compacted array
  }
  start[n] = kept;
  std::partial_sum(offset_.begin(), offset_.end(), offset_.begin());
  adj_.resize(offset_[n]);
  std::vector<int64_t> pos(offset_.begin(), offset_.end() - 1);
  for (int64_t a = 0; a < n; ++a)
    for (int64_t i = start[a]; i < start[a + 1]; ++i) {
      const int64_t b = upper[i];
      adj_[pos[a]++] = b;
      adj_[pos[b]++] = a;
    }
  ascending_ = ascending_order(values_); // the one total order (value, id)
}

} // namespace hoct
