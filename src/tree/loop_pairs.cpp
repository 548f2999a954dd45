#include "tree/loop_pairs.hpp"

#include "tree/union_find.hpp"

#include <algorithm>
#include <map>

namespace hoct {

std::vector<PersistencePair> loop_pairs(const ContourTree &g) {
  std::vector<PersistencePair> out;
  for (LoopCycle &c : loop_cycles(g))
    out.push_back(c.pair);
  return out;
}

std::vector<LoopCycle> loop_cycles(const ContourTree &g) {
  const int64_t n = g.size(), m = static_cast<int64_t>(g.arcs.size());
  std::vector<LoopCycle> out;
  if (graph_loops(g) == 0)
    return out;
  // The 2-core: arcs off every leaf removed until none is left (they carry no cycle).
  std::vector<std::vector<int64_t>> at(static_cast<std::size_t>(n));
  for (int64_t a = 0; a < m; ++a)
    for (int64_t v : g.arcs[a])
      at[v].push_back(a);
  std::vector<int32_t> degree(static_cast<std::size_t>(n));
  std::vector<uint8_t> alive(static_cast<std::size_t>(m), 1);
  std::vector<int64_t> leaves;
  for (int64_t v = 0; v < n; ++v) {
    degree[v] = static_cast<int32_t>(at[v].size());
    if (degree[v] == 1)
      leaves.push_back(v);
  }
  while (!leaves.empty()) {
    const int64_t v = leaves.back();
    leaves.pop_back();
    for (int64_t a : at[v])
      if (alive[a]) {
        alive[a] = 0;
        for (int64_t w : g.arcs[a])
          if (--degree[w] == 1)
            leaves.push_back(w);
      }
  }
  // Arcs ranked by their lower end, highest first (ties: the higher upper end first): a cycle's
  // lowest arc is the one of largest rank, and its lower end is the cycle's bottom.
  std::vector<int64_t> order;
  for (int64_t a = 0; a < m; ++a)
    if (alive[a])
      order.push_back(a);
  std::sort(order.begin(), order.end(), [&](int64_t x, int64_t y) {
    return g.arcs[x][0] != g.arcs[y][0] ? g.arcs[x][0] > g.arcs[y][0] : x > y;
  });
  std::vector<int64_t> rank(static_cast<std::size_t>(m), -1);
  for (std::size_t k = 0; k < order.size(); ++k)
    rank[order[k]] = static_cast<int64_t>(k);

  // The ascending sweep: a spanning forest of the sublevel sets grown node by node; an arc down
  // from node v to a node already connected to v closes a cycle (forest path + the arc) with
  // top v. Cycles as sorted rank lists.
  UnionFind uf(static_cast<std::size_t>(n));
  std::vector<int64_t> parent(static_cast<std::size_t>(n), -1), parent_arc(n, -1);
  std::vector<std::vector<int64_t>> below(static_cast<std::size_t>(n));
  for (int64_t a : order)
    below[g.arcs[a][1]].push_back(a);
  // Forest edges are added by re-rooting the smaller tree; paths found by walking to the root.
  auto reroot = [&](int64_t v) {
    int64_t prev = -1, prev_arc = -1, cur = v;
    while (cur >= 0) {
      const int64_t next = parent[cur], next_arc = parent_arc[cur];
      parent[cur] = prev;
      parent_arc[cur] = prev_arc;
      prev = cur;
      prev_arc = next_arc;
      cur = next;
    }
  };
  std::vector<int64_t> size(static_cast<std::size_t>(n), 1);
  std::map<int64_t, std::vector<int64_t>> by_pivot; // reduced cycles by their lowest arc
  std::vector<int64_t> path_u, path_w;
  for (int64_t v = 0; v < n; ++v)
    for (int64_t a : below[v]) {
      const int64_t w = g.arcs[a][0];
      const int64_t rv = uf.find(v), rw = uf.find(w);
      if (rv != rw) {
        // Hang the smaller tree from the other through arc a.
        const bool hang_w = size[rw] <= size[rv];
        const int64_t x = hang_w ? w : v, y = hang_w ? v : w;
        reroot(x);
        parent[x] = y;
        parent_arc[x] = a;
        uf.unite(rv, rw);
        size[uf.find(v)] = size[rv] + size[rw];
        continue;
      }
      // The cycle: the forest path from w to v, and arc a.
      std::vector<int64_t> cycle{rank[a]};
      std::vector<int64_t> ancestors;
      for (int64_t x = w; x >= 0; x = parent[x])
        ancestors.push_back(x);
      std::sort(ancestors.begin(), ancestors.end());
      int64_t meet = v;
      for (; !std::binary_search(ancestors.begin(), ancestors.end(), meet); meet = parent[meet])
        cycle.push_back(rank[parent_arc[meet]]);
      for (int64_t x = w; x != meet; x = parent[x])
        cycle.push_back(rank[parent_arc[x]]);
      std::sort(cycle.begin(), cycle.end());
      // Reduce: add the earlier cycle of the same lowest arc until the lowest arc is new.
      while (!cycle.empty()) {
        auto it = by_pivot.find(cycle.back());
        if (it == by_pivot.end())
          break;
        std::vector<int64_t> sum;
        std::set_symmetric_difference(cycle.begin(), cycle.end(), it->second.begin(),
                                      it->second.end(), std::back_inserter(sum));
        cycle = std::move(sum);
      }
      if (cycle.empty())
        continue; // cannot happen for an independent cycle
      const int64_t bottom = g.arcs[order[cycle.back()]][0];
      LoopCycle loop{{PersistencePair::Kind::Loop, v, bottom, g.values[v], g.values[bottom]}, {}};
      for (int64_t r : cycle)
        loop.arcs.push_back(order[r]);
      out.push_back(std::move(loop));
      by_pivot.emplace(cycle.back(), std::move(cycle));
    }
  return out;
}

} // namespace hoct
