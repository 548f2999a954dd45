#include "tree/sublevel_forest.hpp"

#include <algorithm>
#include <array>

namespace hoct {

SublevelForest::SublevelForest(Side side, std::span<const int64_t> ascending,
                               std::span<const int64_t> offset, std::span<const int64_t> adj,
                               std::span<const int64_t> adj_edge) {
  const int64_t n = static_cast<int64_t>(ascending.size());
  // The node of rank r in the sweep's order.
  auto order = [&](int64_t r) {
    return side == Side::Sublevel ? ascending[r] : ascending[n - 1 - r];
  };
  std::vector<int64_t> rank(static_cast<std::size_t>(n));
  for (int64_t r = 0; r < n; ++r)
    rank[order(r)] = r;
  // Kruskal's construction in the sweep's order: the forest's edges (v, w, edge id).
  std::vector<int64_t> set(static_cast<std::size_t>(n));
  for (int64_t v = 0; v < n; ++v)
    set[v] = v;
  auto find = [&](int64_t v) {
    while (set[v] != v)
      v = set[v] = set[set[v]];
    return v;
  };
  std::vector<std::array<int64_t, 3>> joins;
  joins.reserve(static_cast<std::size_t>(std::max<int64_t>(n - 1, 0)));
  for (int64_t r = 0; r < n; ++r)
    for (int64_t v = order(r), k = offset[v]; k < offset[v + 1]; ++k) {
      const int64_t w = adj[k];
      if (rank[w] >= rank[v])
        continue;
      const int64_t rw = find(w), rv = find(v);
      if (rw == rv)
        continue;
      set[rw] = rv;
      joins.push_back({v, w, adj_edge[k]});
    }
  rank = {};
  set = {};
  // The forest in CSR form, then rooted at each component's last node (breadth first).
  std::vector<int64_t> start(static_cast<std::size_t>(n + 1), 0);
  for (const auto &j : joins) {
    ++start[j[0] + 1];
    ++start[j[1] + 1];
  }
  for (int64_t v = 0; v < n; ++v)
    start[v + 1] += start[v];
  std::vector<int64_t> next(start.begin(), start.end() - 1);
  std::vector<std::array<int64_t, 2>> link(2 * joins.size()); // (neighbour, edge id)
  for (const auto &j : joins) {
    link[next[j[0]]++] = {j[1], j[2]};
    link[next[j[1]]++] = {j[0], j[2]};
  }
  joins = {};
  next = {};
  parent_.assign(static_cast<std::size_t>(n), -2); // -2: not reached yet
  parent_edge_.assign(static_cast<std::size_t>(n), -1);
  depth_.assign(static_cast<std::size_t>(n), 0);
  std::vector<int64_t> queue;
  for (int64_t r = n - 1; r >= 0; --r) {
    const int64_t root = order(r);
    if (parent_[root] != -2)
      continue;
    parent_[root] = -1;
    queue.assign(1, root);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int64_t v = queue[q];
      for (int64_t k = start[v]; k < start[v + 1]; ++k) {
        const auto [w, e] = link[k];
        if (parent_[w] != -2)
          continue;
        parent_[w] = v;
        parent_edge_[w] = e;
        depth_[w] = depth_[v] + 1;
        queue.push_back(w);
      }
    }
  }
}

bool SublevelForest::path(int64_t a, int64_t b, std::vector<int64_t> &nodes,
                          std::vector<int64_t> &edges) const {
  // Climb from the deeper end until both are at one depth, then from both until they meet;
  // b's side is collected apart and appended reversed.
  std::vector<int64_t> up_a = {a}, up_b = {b}, edge_a, edge_b;
  int64_t x = a, y = b;
  while (depth_[x] > depth_[y]) {
    edge_a.push_back(parent_edge_[x]);
    up_a.push_back(x = parent_[x]);
  }
  while (depth_[y] > depth_[x]) {
    edge_b.push_back(parent_edge_[y]);
    up_b.push_back(y = parent_[y]);
  }
  while (x != y) {
    if (parent_[x] < 0) // two roots: different components
      return false;
    edge_a.push_back(parent_edge_[x]);
    up_a.push_back(x = parent_[x]);
    edge_b.push_back(parent_edge_[y]);
    up_b.push_back(y = parent_[y]);
  }
  nodes = std::move(up_a);
  nodes.insert(nodes.end(), up_b.rbegin() + 1, up_b.rend());
  edges = std::move(edge_a);
  edges.insert(edges.end(), edge_b.rbegin(), edge_b.rend());
  return true;
}

} // namespace hoct
