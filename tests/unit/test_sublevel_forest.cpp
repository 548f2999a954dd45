// The minimax spanning forests against a brute force: on random grids with missing edges, the
// sublevel forest's path between two nodes has the smallest largest value of any path between
// them (the lowest level at which they are connected, found by trying every level), the
// superlevel forest's the largest smallest value; both are walks through the graph, and there
// is no path between nodes of different pieces.
#include "tree/sublevel_forest.hpp"

#include "tree/node_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>

namespace hoct {
namespace {

struct Grid {
  std::vector<double> values;
  std::vector<std::array<int64_t, 2>> edges;
  std::vector<int64_t> offset, adj, adj_edge;
};

Grid random_grid(int side, double missing, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Grid g;
  const int n = side * side;
  for (int i = 0; i < n; ++i) // a few ties, to exercise the order's ids
    g.values.push_back(std::floor(u(rng) * 200) / 200);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      for (auto [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}})
        if (x + dx < side && y + dy < side && u(rng) >= missing)
          g.edges.push_back({y * side + x, (y + dy) * side + x + dx});
  g.offset.assign(n + 1, 0);
  for (const auto &e : g.edges) {
    ++g.offset[e[0] + 1];
    ++g.offset[e[1] + 1];
  }
  for (int v = 0; v < n; ++v)
    g.offset[v + 1] += g.offset[v];
  std::vector<int64_t> fill(g.offset.begin(), g.offset.end() - 1);
  g.adj.resize(g.offset[n]);
  g.adj_edge.resize(g.offset[n]);
  for (std::size_t i = 0; i < g.edges.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      g.adj[fill[g.edges[i][k]]] = g.edges[i][1 - k];
      g.adj_edge[fill[g.edges[i][k]]++] = static_cast<int64_t>(i);
    }
  return g;
}

// Whether b is reachable from a through nodes with values in [lo, hi].
bool reachable(const Grid &g, int64_t a, int64_t b, double lo, double hi) {
  if (g.values[a] < lo || g.values[a] > hi)
    return false;
  std::vector<char> seen(g.values.size(), 0);
  std::vector<int64_t> queue = {a};
  seen[a] = 1;
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (int64_t k = g.offset[queue[q]]; k < g.offset[queue[q] + 1]; ++k) {
      const int64_t w = g.adj[k];
      if (!seen[w] && g.values[w] >= lo && g.values[w] <= hi) {
        seen[w] = 1;
        queue.push_back(w);
      }
    }
  return seen[b];
}

TEST(SublevelForest, PathsAreMinimaxWalksAgainstABruteForce) {
  using Side = SublevelForest::Side;
  for (uint64_t seed : {1, 2, 3}) {
    const Grid g = random_grid(24, seed == 3 ? 0.45 : 0.2, seed);
    const std::vector<int64_t> order = ascending_order(g.values);
    const SublevelForest below(Side::Sublevel, order, g.offset, g.adj, g.adj_edge);
    const SublevelForest above(Side::Superlevel, order, g.offset, g.adj, g.adj_edge);
    const std::set<double> levels(g.values.begin(), g.values.end());
    std::mt19937_64 rng(seed + 100);
    int connected = 0, apart = 0;
    for (int trial = 0; trial < 150; ++trial) {
      const int64_t a = static_cast<int64_t>(rng() % g.values.size());
      const int64_t b = static_cast<int64_t>(rng() % g.values.size());
      const bool joined = reachable(g, a, b, -INFINITY, INFINITY);
      for (Side side : {Side::Sublevel, Side::Superlevel}) {
        const SublevelForest &f = side == Side::Sublevel ? below : above;
        std::vector<int64_t> nodes, edges;
        const bool found = f.path(a, b, nodes, edges);
        ASSERT_EQ(found, joined) << a << " to " << b;
        if (!found) {
          ++apart;
          continue;
        }
        ++connected;
        ASSERT_EQ(nodes.front(), a);
        ASSERT_EQ(nodes.back(), b);
        ASSERT_EQ(edges.size() + 1, nodes.size());
        for (std::size_t i = 0; i < edges.size(); ++i) {
          const auto &e = g.edges[edges[i]];
          EXPECT_TRUE((e[0] == nodes[i] && e[1] == nodes[i + 1]) ||
                      (e[1] == nodes[i] && e[0] == nodes[i + 1]))
              << "step " << i << " is not its edge";
        }
        EXPECT_EQ(std::set<int64_t>(nodes.begin(), nodes.end()).size(), nodes.size())
            << "a forest path visits no node twice";
        // The brute force: the lowest level (the highest, above) at which a and b connect.
        double best = side == Side::Sublevel ? INFINITY : -INFINITY;
        for (double t : levels)
          if (side == Side::Sublevel ? reachable(g, a, b, -INFINITY, t)
                                     : reachable(g, a, b, t, INFINITY))
            best = side == Side::Sublevel ? std::min(best, t) : std::max(best, t);
        double extreme = g.values[a];
        for (int64_t v : nodes)
          extreme = side == Side::Sublevel ? std::max(extreme, g.values[v])
                                           : std::min(extreme, g.values[v]);
        EXPECT_EQ(extreme, best) << a << " to " << b;
      }
    }
    EXPECT_GT(connected, 100);
    if (seed == 3) {
      EXPECT_GT(apart, 5); // many pieces at 45% of the edges missing
    }
  }
}

} // namespace
} // namespace hoct
