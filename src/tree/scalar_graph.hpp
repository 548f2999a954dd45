// A graph whose nodes carry scalar values, ordered by one total order everywhere:
// (value, id). Edges are undirected; the join sweep follows them downwards, the split sweep
// upwards. For a piecewise-linear field this is the mesh's 1-skeleton; for the exact
// higher-order tree, the certified connections between critical points.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// a before b in the total order (value, then id).
inline bool node_less(double va, int64_t a, double vb, int64_t b) {
  return va < vb || (va == vb && a < b);
}

// An undirected edge between nodes a and b (trivial, so that large edge arrays can be filled in
// parallel without being zeroed first).
struct GraphEdge {
  int64_t a, b;
};

class ScalarGraph {
public:
  // Builds the adjacency (CSR) of n nodes from undirected edges; self-loops and duplicate edges
  // are dropped. The result does not depend on the order of the edges.
  ScalarGraph(std::vector<double> values, std::span<const GraphEdge> edges);

  int64_t size() const { return static_cast<int64_t>(values_.size()); }
  double value(int64_t v) const { return values_[v]; }
  const std::vector<double> &values() const { return values_; }
  std::span<const int64_t> neighbors(int64_t v) const {
    return {adj_.data() + offset_[v], static_cast<std::size_t>(offset_[v + 1] - offset_[v])};
  }
  bool less(int64_t a, int64_t b) const { return node_less(values_[a], a, values_[b], b); }
  // Nodes sorted ascending by (value, id); computed once.
  const std::vector<int64_t> &ascending() const { return ascending_; }
  int64_t num_edges() const { return static_cast<int64_t>(adj_.size() / 2); }

private:
  std::vector<double> values_;
  std::vector<int64_t> offset_, adj_, ascending_;
};

} // namespace hoct
