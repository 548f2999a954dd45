#include "tree/merge_tree.hpp"

#include "tree/union_find.hpp"

namespace hoct {
namespace {

// Sweeps the nodes in `order`; `before(u, v)` says u was swept before v.
template <class Order>
MergeTree sweep(const ScalarGraph &g, const Order &order, MergeTree::Kind kind) {
  const int64_t n = g.size();
  MergeTree t;
  t.kind = kind;
  t.parent.assign(n, -1);
  t.children.assign(n, 0);
  std::vector<int64_t> rank(n), top(n);
  for (int64_t i = 0; i < n; ++i)
    rank[order(i)] = i;
  UnionFind uf(n);
  for (int64_t i = 0; i < n; ++i) {
    const int64_t v = order(i);
    top[v] = v;
    for (int64_t u : g.neighbors(v)) {
      if (rank[u] > rank[v])
        continue;
      const int64_t ru = uf.find(u), rv = uf.find(v);
      if (ru == rv)
        continue;
      // The component of u so far ends at its most recent node; it continues at v.
      const int64_t low = top[ru];
      t.parent[low] = v;
      ++t.children[v];
      uf.unite(ru, rv);
      top[uf.find(v)] = v;
    }
    top[uf.find(v)] = v;
  }
  for (int64_t v = 0; v < n; ++v)
    t.roots += t.parent[v] < 0;
  return t;
}

} // namespace

MergeTree join_tree(const ScalarGraph &g) {
  const auto &asc = g.ascending();
  return sweep(
      g, [&](int64_t i) { return asc[i]; }, MergeTree::Kind::Join);
}

MergeTree split_tree(const ScalarGraph &g) {
  const auto &asc = g.ascending();
  const int64_t n = g.size();
  return sweep(
      g, [&](int64_t i) { return asc[n - 1 - i]; }, MergeTree::Kind::Split);
}

} // namespace hoct
