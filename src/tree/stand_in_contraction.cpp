#include "tree/stand_in_contraction.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>

namespace hoct {

StandInContraction contract_stand_in_arcs(const ContourTree &in,
                                          const std::vector<double> &slack_in) {
  const int64_t n = in.size();
  StandInContraction out;
  std::vector<std::vector<int64_t>> adj(static_cast<std::size_t>(n));
  for (const auto &a : in.arcs) {
    adj[a[0]].push_back(a[1]);
    adj[a[1]].push_back(a[0]);
  }
  // Per merged group (at its surviving node): the slack, and the span of original values.
  std::vector<double> slack(slack_in), lo(in.values), hi(in.values);
  std::vector<char> alive(static_cast<std::size_t>(n), 1);
  int64_t alive_count = n;
  auto up = [&](int64_t v) {
    return static_cast<int>(
        std::count_if(adj[v].begin(), adj[v].end(), [v](int64_t u) { return u > v; }));
  };
  auto linked = [&](int64_t a, int64_t b) {
    return std::find(adj[a].begin(), adj[a].end(), b) != adj[a].end();
  };
  auto unlink = [&](int64_t a, int64_t b) {
    adj[a].erase(std::find(adj[a].begin(), adj[a].end(), b));
  };
  using Item = std::tuple<double, int64_t, int64_t>; // length, lower end, higher end
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto push = [&](int64_t a, int64_t b) {
    if (a > b)
      std::swap(a, b);
    if (slack[a] >= 0 && slack[b] >= 0)
      heap.push({in.values[b] - in.values[a], a, b});
  };
  for (const auto &a : in.arcs)
    push(a[0], a[1]);

  while (!heap.empty() && alive_count > 2) {
    const auto [length, a, b] = heap.top();
    heap.pop();
    if (!alive[a] || !alive[b] || !linked(a, b))
      continue;
    const double allowed = 2 * std::max(slack[a], slack[b]);
    // Arcs of length zero (plateaus, equal values along a ridge) are contract_flat's to merge
    // (--keep-flat keeps them).
    if (!(length > 0) || !(length <= allowed) ||
        !(std::max(hi[a], hi[b]) - std::min(lo[a], lo[b]) <= allowed))
      continue;
    const int up_a = up(a), down_b = static_cast<int>(adj[b].size()) - up(b);
    // Keep b (the higher value) if a has no other arc up: a's other neighbours are below it.
    // Keep a if b has no other arc down: b's other neighbours are above it.
    int64_t keep, drop;
    if (up_a == 1)
      keep = b, drop = a;
    else if (down_b == 1)
      keep = a, drop = b;
    else
      continue;
    unlink(keep, drop);
    unlink(drop, keep);
    for (const int64_t x : adj[drop]) {
      unlink(x, drop);
      adj[x].push_back(keep);
      adj[keep].push_back(x);
    }
    adj[drop].clear();
    alive[drop] = 0;
    --alive_count;
    ++out.contracted;
    slack[keep] = std::max(slack[keep], slack[drop]);
    lo[keep] = std::min(lo[keep], lo[drop]);
    hi[keep] = std::max(hi[keep], hi[drop]);
    // Regular now (one arc up, one down): spliced out, its two arcs become one.
    if (adj[keep].size() == 2 && up(keep) == 1 && alive_count > 2) {
      const int64_t p = adj[keep][0], q = adj[keep][1];
      unlink(p, keep);
      unlink(q, keep);
      adj[keep].clear();
      alive[keep] = 0;
      --alive_count;
      adj[p].push_back(q);
      adj[q].push_back(p);
      push(p, q);
      continue;
    }
    for (const int64_t x : adj[keep])
      push(keep, x);
  }

  ContourTree contracted;
  std::vector<int64_t> index(static_cast<std::size_t>(n), -1);
  for (int64_t v = 0; v < n; ++v)
    if (alive[v]) {
      index[v] = contracted.size();
      contracted.nodes.push_back(in.nodes[v]);
      contracted.values.push_back(in.values[v]);
    }
  for (int64_t v = 0; v < n; ++v)
    for (const int64_t u : adj[v])
      if (u > v)
        contracted.arcs.push_back({index[v], index[u]});
  std::sort(contracted.arcs.begin(), contracted.arcs.end());
  out.tree = reduce(contracted);
  return out;
}

} // namespace hoct
