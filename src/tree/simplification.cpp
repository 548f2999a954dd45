#include "tree/simplification.hpp"

#include "tree/union_find.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <set>
#include <tuple>

namespace hoct {

Simplification simplify(const ContourTree &in, double threshold) {
  const int64_t n = in.size();
  // Adjacency as sets of (neighbour, arc id); arcs are merged when a regular node is spliced.
  std::vector<std::set<std::pair<int64_t, int64_t>>> adj(n);
  std::vector<std::array<int64_t, 2>> arc_ends;
  for (const auto &a : in.arcs) {
    const int64_t id = static_cast<int64_t>(arc_ends.size());
    arc_ends.push_back(a);
    adj[a[0]].insert({a[1], id});
    adj[a[1]].insert({a[0], id});
  }
  UnionFind arc_sets(in.arcs.size() * 2 + 1);
  // Node order is the total order: node indices are ascending.
  auto up_degree = [&](int64_t v) {
    int d = 0;
    for (const auto &[u, id] : adj[v])
      d += u > v;
    return d;
  };
  auto down_degree = [&](int64_t v) { return static_cast<int>(adj[v].size()) - up_degree(v); };
  std::vector<char> removed(n, 0);
  int64_t alive = n;
  // Leaf candidates: (persistence, leaf) in a min-heap; validated when popped.
  using Item = std::tuple<double, int64_t, int64_t>; // persistence, leaf, saddle
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto push_leaf = [&](int64_t leaf) {
    if (removed[leaf] || adj[leaf].size() != 1)
      return;
    const int64_t s = adj[leaf].begin()->first;
    heap.push({std::abs(in.values[leaf] - in.values[s]), leaf, s});
  };
  for (int64_t v = 0; v < n; ++v)
    push_leaf(v);

  Simplification out;
  struct Pruned {
    int64_t leaf, saddle, arc;
    double persistence;
  };
  std::vector<Pruned> order;
  std::vector<int64_t> absorbed_into(n, -1); // arc that swallowed a spliced node
  auto snapshot = [&] {
    // The simplified tree: nodes still alive, arcs between them.
    std::vector<int64_t> index(n, -1);
    for (int64_t v = 0; v < n; ++v)
      if (!removed[v]) {
        index[v] = out.tree.size();
        out.tree.nodes.push_back(in.nodes[v]);
        out.tree.values.push_back(in.values[v]);
        out.kept.push_back(v);
      }
    for (int64_t v = 0; v < n; ++v)
      if (!removed[v])
        for (const auto &[u, id] : adj[v])
          if (u > v)
            out.tree.arcs.push_back({index[v], index[u]});
    std::sort(out.tree.arcs.begin(), out.tree.arcs.end());
  };
  // Prunes valid leaves while the smallest candidate persistence is below `limit`.
  auto prune = [&](double limit) {
    while (!heap.empty() && alive > 2 && std::get<0>(heap.top()) < limit) {
      const auto [pers, leaf, s] = heap.top();
      heap.pop();
      if (removed[leaf] || adj[leaf].size() != 1 || adj[leaf].begin()->first != s)
        continue;
      const bool is_max = s < leaf;
      // Keep a valid contour tree: the saddle must keep an arc on the leaf's side.
      if ((is_max && up_degree(s) < 2) || (!is_max && down_degree(s) < 2))
        continue;
      const int64_t arc = adj[leaf].begin()->second;
      order.push_back({leaf, s, arc, pers});
      adj[s].erase({leaf, arc});
      adj[leaf].clear();
      removed[leaf] = 1;
      --alive;
      // A saddle left regular (one arc up, one down) is spliced out.
      if (adj[s].size() == 2 && up_degree(s) == 1) {
        const auto [a, ida] = *adj[s].begin();
        const auto [b, idb] = *std::next(adj[s].begin());
        adj[a].erase({s, ida});
        adj[b].erase({s, idb});
        const int64_t merged = static_cast<int64_t>(arc_ends.size());
        arc_ends.push_back({std::min(a, b), std::max(a, b)});
        arc_sets.unite(ida, merged);
        arc_sets.unite(idb, merged);
        adj[a].insert({b, merged});
        adj[b].insert({a, merged});
        adj[s].clear();
        removed[s] = 1;
        --alive;
        absorbed_into[s] = merged;
        push_leaf(a);
        push_leaf(b);
      } else if (adj[s].size() == 1) {
        push_leaf(s);
      }
    }
  };
  prune(threshold);
  snapshot();
  out.pruned_leaves = static_cast<int64_t>(order.size());
  prune(INFINITY);

  // Branches: the root is the last arc; every pruned leaf a branch.
  std::vector<int64_t> label(arc_ends.size(), -1); // arc-set root -> branch
  int64_t root_lo = -1, root_hi = -1, root_arc = -1;
  for (int64_t v = 0; v < n; ++v)
    if (!removed[v])
      for (const auto &[u, id] : adj[v])
        if (u > v)
          root_lo = v, root_hi = u, root_arc = id;
  out.branches.push_back(
      {root_hi, root_lo, root_hi >= 0 ? in.values[root_hi] - in.values[root_lo] : 0.0, -1, 0});
  if (root_arc >= 0)
    label[arc_sets.find(root_arc)] = 0;
  // Then the pruned leaves in reverse pruning order, so parents come before their children.
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    label[arc_sets.find(it->arc)] = static_cast<int64_t>(out.branches.size());
    out.branches.push_back({it->leaf, it->saddle, it->persistence, -1, 0});
  }
  for (std::size_t b = 1; b < out.branches.size(); ++b) {
    const int64_t s = out.branches[b].saddle;
    // The saddle was spliced into an arc (or is an end of the root branch).
    int64_t parent = 0;
    if (absorbed_into[s] >= 0)
      parent = label[arc_sets.find(absorbed_into[s])];
    out.branches[b].parent = parent >= 0 ? parent : 0;
  }
  // Depths (parents come before children in persistence order, so one pass suffices).
  for (std::size_t b = 1; b < out.branches.size(); ++b)
    out.branches[b].depth = out.branches[out.branches[b].parent].depth + 1;
  return out;
}

std::vector<std::vector<int64_t>> branch_children(const std::vector<Branch> &b) {
  std::vector<std::vector<int64_t>> children(b.size());
  for (std::size_t i = 1; i < b.size(); ++i)
    children[b[i].parent].push_back(static_cast<int64_t>(i));
  for (auto &c : children)
    std::sort(c.begin(), c.end(),
              [&](int64_t x, int64_t y) { return b[x].persistence > b[y].persistence; });
  return children;
}

} // namespace hoct
