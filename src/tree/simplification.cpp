#include "tree/simplification.hpp"

#include "tree/union_find.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <tuple>

namespace hoct {

namespace {

// The arcs at each node, changing as leaves are pruned and regular nodes spliced out: each node's
// arcs in a slice of its original degree (a node's degree never grows: a splice replaces one arc
// at each neighbour by the merged one), every arc knowing its place at both ends, so removing
// one is a swap with its slice's last; up-degrees kept as counts.
class Adjacency {
public:
  explicit Adjacency(const ContourTree &t) : first_(t.size() + 1, 0), count_(t.size(), 0) {
    const int64_t n = t.size();
    up_.assign(static_cast<std::size_t>(n), 0);
    for (const auto &a : t.arcs) {
      ++first_[a[0] + 1];
      ++first_[a[1] + 1];
    }
    for (int64_t v = 0; v < n; ++v)
      first_[v + 1] += first_[v];
    slot_.resize(static_cast<std::size_t>(first_[n]));
    ends_.reserve(t.arcs.size() * 2);
    pos_.reserve(t.arcs.size() * 2);
    for (const auto &a : t.arcs)
      add(a[0], a[1]);
  }
  // Adds the arc lo - hi (lo < hi, the lower node in the total order); returns its id.
  int64_t add(int64_t lo, int64_t hi) {
    const int64_t id = static_cast<int64_t>(ends_.size());
    ends_.push_back({lo, hi});
    pos_.push_back({count_[lo], count_[hi]});
    slot_[first_[lo] + count_[lo]++] = id;
    slot_[first_[hi] + count_[hi]++] = id;
    ++up_[lo];
    return id;
  }
  void remove(int64_t id) {
    for (int side = 0; side < 2; ++side) {
      const int64_t v = ends_[id][side];
      const int64_t i = pos_[id][side], last = slot_[first_[v] + --count_[v]];
      slot_[first_[v] + i] = last;
      pos_[last][ends_[last][0] == v ? 0 : 1] = i;
    }
    --up_[ends_[id][0]];
  }
  int64_t degree(int64_t v) const { return count_[v]; }
  int up_degree(int64_t v) const { return up_[v]; }
  int down_degree(int64_t v) const { return static_cast<int>(count_[v]) - up_[v]; }
  // Arc k (0 .. degree - 1) at v, and its other end.
  int64_t arc(int64_t v, int64_t k) const { return slot_[first_[v] + k]; }
  int64_t other(int64_t id, int64_t v) const {
    return ends_[id][0] == v ? ends_[id][1] : ends_[id][0];
  }
  const std::array<int64_t, 2> &ends(int64_t id) const { return ends_[id]; }
  std::size_t arcs() const { return ends_.size(); }

private:
  std::vector<int64_t> first_, count_, slot_;
  std::vector<int32_t> up_;
  std::vector<std::array<int64_t, 2>> ends_, pos_;
};

} // namespace

Simplification simplify(const ContourTree &in, double threshold) {
  const int64_t n = in.size();
  // Arcs are merged when a regular node is spliced; node order is the total order (node
  // indices are ascending), so an arc's lower end is its first.
  Adjacency adj(in);
  UnionFind arc_sets(in.arcs.size() * 2 + 1);
  std::vector<char> removed(n, 0);
  int64_t alive = n;
  // Leaf candidates: (persistence, leaf) in a min-heap; validated when popped.
  using Item = std::tuple<double, int64_t, int64_t>; // persistence, leaf, saddle
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto push_leaf = [&](int64_t leaf) {
    if (removed[leaf] || adj.degree(leaf) != 1)
      return;
    const int64_t s = adj.other(adj.arc(leaf, 0), leaf);
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
        for (int64_t k = 0; k < adj.degree(v); ++k) {
          const int64_t u = adj.other(adj.arc(v, k), v);
          if (u > v)
            out.tree.arcs.push_back({index[v], index[u]});
        }
    std::sort(out.tree.arcs.begin(), out.tree.arcs.end());
  };
  // Prunes valid leaves while the smallest candidate persistence is below `limit`.
  auto prune = [&](double limit) {
    while (!heap.empty() && alive > 2 && std::get<0>(heap.top()) < limit) {
      const auto [pers, leaf, s] = heap.top();
      heap.pop();
      if (removed[leaf] || adj.degree(leaf) != 1 || adj.other(adj.arc(leaf, 0), leaf) != s)
        continue;
      const bool is_max = s < leaf;
      // Keep a valid contour tree: the saddle must keep an arc on the leaf's side.
      if ((is_max && adj.up_degree(s) < 2) || (!is_max && adj.down_degree(s) < 2))
        continue;
      const int64_t arc = adj.arc(leaf, 0);
      order.push_back({leaf, s, arc, pers});
      adj.remove(arc);
      removed[leaf] = 1;
      --alive;
      // A saddle left regular (one arc up, one down) is spliced out.
      if (adj.degree(s) == 2 && adj.up_degree(s) == 1) {
        const int64_t ida = adj.arc(s, 0), idb = adj.arc(s, 1);
        const int64_t a = adj.other(ida, s), b = adj.other(idb, s);
        adj.remove(ida);
        adj.remove(idb);
        const int64_t merged = adj.add(std::min(a, b), std::max(a, b));
        arc_sets.unite(ida, merged);
        arc_sets.unite(idb, merged);
        removed[s] = 1;
        --alive;
        absorbed_into[s] = merged;
        push_leaf(a);
        push_leaf(b);
      } else if (adj.degree(s) == 1) {
        push_leaf(s);
      }
    }
  };
  prune(threshold);
  snapshot();
  out.pruned_leaves = static_cast<int64_t>(order.size());
  prune(INFINITY);

  // Branches: the root is the last arc (of a graph's remaining core, the last in the order of
  // (lower end, upper end, id)); every pruned leaf a branch.
  std::vector<int64_t> label(adj.arcs(), -1); // arc-set root -> branch
  int64_t root_lo = -1, root_hi = -1, root_arc = -1;
  for (int64_t v = 0; v < n; ++v)
    if (!removed[v])
      for (int64_t k = 0; k < adj.degree(v); ++k) {
        const int64_t id = adj.arc(v, k), u = adj.other(id, v);
        if (u > v && std::tie(v, u, id) > std::tie(root_lo, root_hi, root_arc))
          root_lo = v, root_hi = u, root_arc = id;
      }
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
