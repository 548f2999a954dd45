#include "tree/contour_tree.hpp"

#include "tree/union_find.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace hoct {

const char *to_string(NodeType t) {
  switch (t) {
  case NodeType::Minimum:
    return "minimum";
  case NodeType::Maximum:
    return "maximum";
  case NodeType::Saddle:
    return "saddle";
  case NodeType::Regular:
    return "regular";
  }
  return "?";
}

std::vector<std::array<int32_t, 2>> ContourTree::degrees() const {
  std::vector<std::array<int32_t, 2>> d(nodes.size(), {0, 0});
  for (const auto &a : arcs) {
    ++d[a[0]][0]; // a[0] is lower: the arc goes up from it
    ++d[a[1]][1];
  }
  return d;
}

std::vector<NodeType> ContourTree::types() const {
  const auto deg = degrees();
  std::vector<NodeType> t(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const int up = deg[i][0], down = deg[i][1];
    if (down == 0 && up > 0)
      t[i] = NodeType::Minimum;
    else if (up == 0 && down > 0)
      t[i] = NodeType::Maximum;
    else if (up == 1 && down == 1)
      t[i] = NodeType::Regular;
    else
      t[i] = NodeType::Saddle; // includes isolated nodes (a one-node component)
  }
  return t;
}

std::vector<std::array<int64_t, 2>> merge_join_split(std::vector<int64_t> jparent,
                                                     std::vector<int32_t> jdown,
                                                     std::vector<int64_t> sparent,
                                                     std::vector<int32_t> sup) {
  const int64_t n = static_cast<int64_t>(jparent.size());
  std::vector<int64_t> jsum(n, 0), ssum(n, 0);
  for (int64_t v = 0; v < n; ++v) {
    if (jparent[v] >= 0)
      jsum[jparent[v]] += v;
    if (sparent[v] >= 0)
      ssum[sparent[v]] += v;
  }
  std::vector<char> removed(n, 0);
  std::vector<int64_t> queue;
  auto is_leaf = [&](int64_t v) {
    return (jdown[v] == 0 && sup[v] <= 1) || (sup[v] == 0 && jdown[v] <= 1);
  };
  for (int64_t v = 0; v < n; ++v)
    if (is_leaf(v))
      queue.push_back(v);
  std::vector<std::array<int64_t, 2>> arcs;
  arcs.reserve(static_cast<std::size_t>(n));
  auto remove_from = [](std::vector<int64_t> &parent, std::vector<int32_t> &count,
                        std::vector<int64_t> &sum, int64_t v) {
    const int64_t p = parent[v];
    const int64_t child = count[v] == 1 ? sum[v] : -1;
    if (p >= 0) {
      sum[p] -= v;
      --count[p];
    }
    if (child >= 0) {
      parent[child] = p;
      if (p >= 0) {
        sum[p] += child;
        ++count[p];
      }
    }
    return p;
  };
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int64_t v = queue[q];
    if (removed[v] || !is_leaf(v))
      continue;
    // A lower leaf's arc goes up, to its join-tree parent; an upper leaf's down, to its split
    // parent. A join root with an upper neighbour left is handled as an upper leaf; the last
    // node of a component has no arc.
    const int64_t other = jdown[v] == 0 && sup[v] <= 1 ? jparent[v] : sparent[v];
    if (other < 0)
      continue;
    arcs.push_back({std::min(v, other), std::max(v, other)});
    removed[v] = 1;
    const int64_t jp = remove_from(jparent, jdown, jsum, v);
    const int64_t sp = remove_from(sparent, sup, ssum, v);
    for (int64_t w : {jp, sp})
      if (w >= 0 && !removed[w] && is_leaf(w))
        queue.push_back(w);
  }
  return arcs;
}

ContourTree merge_trees(const ScalarGraph &g, const MergeTree &join, const MergeTree &split) {
  const int64_t n = g.size();
  if (join.size() != n || split.size() != n)
    throw std::invalid_argument("merge_trees: trees and graph differ in size");
  ContourTree ct;
  ct.nodes = g.ascending();
  ct.values.resize(n);
  std::vector<int64_t> index(n);
  for (int64_t i = 0; i < n; ++i) {
    index[ct.nodes[i]] = i;
    ct.values[i] = g.value(ct.nodes[i]);
  }
  ct.arcs = merge_join_split(join.parent, join.children, split.parent, split.children);
  for (auto &a : ct.arcs) {
    a = {index[a[0]], index[a[1]]};
    if (a[0] > a[1])
      std::swap(a[0], a[1]);
  }
  std::sort(ct.arcs.begin(), ct.arcs.end());
  return ct;
}

std::vector<int64_t> sort_arcs(std::vector<std::array<int64_t, 2>> &arcs) {
  std::vector<int64_t> order(arcs.size()), rank(arcs.size());
  std::iota(order.begin(), order.end(), int64_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](int64_t x, int64_t y) { return arcs[x] < arcs[y]; });
  std::vector<std::array<int64_t, 2>> sorted(arcs.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    sorted[k] = arcs[order[k]];
    rank[order[k]] = static_cast<int64_t>(k);
  }
  arcs = std::move(sorted);
  return rank;
}

int64_t graph_loops(const ContourTree &g) {
  UnionFind uf(static_cast<std::size_t>(g.size()));
  int64_t components = g.size();
  for (const auto &a : g.arcs)
    components -= uf.unite(a[0], a[1]) ? 1 : 0;
  return static_cast<int64_t>(g.arcs.size()) - g.size() + components;
}

ContourTree reduce(const ContourTree &aug) {
  const int64_t n = aug.size();
  const auto deg = aug.degrees();
  // Adjacency of the augmented tree.
  std::vector<int64_t> off(n + 1, 0), adj(2 * aug.arcs.size());
  for (const auto &a : aug.arcs) {
    ++off[a[0] + 1];
    ++off[a[1] + 1];
  }
  for (int64_t i = 0; i < n; ++i)
    off[i + 1] += off[i];
  std::vector<int64_t> fill(off.begin(), off.end() - 1);
  for (const auto &a : aug.arcs) {
    adj[fill[a[0]]++] = a[1];
    adj[fill[a[1]]++] = a[0];
  }
  auto regular = [&](int64_t i) { return deg[i][0] == 1 && deg[i][1] == 1; };
  ContourTree r;
  std::vector<int64_t> new_index(n, -1);
  for (int64_t i = 0; i < n; ++i)
    if (!regular(i)) {
      new_index[i] = r.size();
      r.nodes.push_back(aug.nodes[i]);
      r.values.push_back(aug.values[i]);
    }
  // From each kept node, follow each upward arc through regular nodes to the next kept node.
  for (int64_t i = 0; i < n; ++i) {
    if (regular(i))
      continue;
    for (int64_t k = off[i]; k < off[i + 1]; ++k) {
      int64_t prev = i, cur = adj[k];
      if (cur < i)
        continue; // only upward arcs (indices are in ascending order)
      while (regular(cur)) {
        const int64_t a = adj[off[cur]], b = adj[off[cur] + 1];
        const int64_t next = a == prev ? b : a;
        prev = cur;
        cur = next;
      }
      r.arcs.push_back({new_index[i], new_index[cur]});
    }
  }
  std::sort(r.arcs.begin(), r.arcs.end());
  return r;
}

ContourTree contour_tree(const ScalarGraph &graph, bool augmented) {
  const MergeTree j = join_tree(graph), s = split_tree(graph);
  ContourTree ct = merge_trees(graph, j, s);
  return augmented ? ct : reduce(ct);
}

} // namespace hoct
