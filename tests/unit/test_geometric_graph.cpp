// The geometric graph's arc paths: within the arc's values where the graph allows it, else below
// the upper end's value or above the lower's (where the join or the split tree connects an arc's
// ends), else any path; one scratch
// serves searches on different graphs; long paths and random grids as walks through the graph.
#include "tree/geometric_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace hoct {
namespace {

// Nodes a (value 0) and b (value 1); c (value 0.5) joins them within the arc's values only when
// `with_c`; d (value -1) joins them below b; e (value 5) joins them above. e's edges come first,
// then d's: a search for any path would go through e.
GeometricGraph diamond(bool with_c) {
  GeometricGraph g({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 2, 0}},
                   {0.0, 1.0, 0.5, -1.0, 5.0});
  g.add_edge(0, 4, std::vector<Vec3>{{0.2, 1, 0}});
  g.add_edge(4, 1, std::vector<Vec3>{{0.8, 1, 0}});
  g.add_edge(0, 3, std::vector<Vec3>{{0.2, -1, 0}});
  g.add_edge(3, 1, std::vector<Vec3>{{0.8, -1, 0}});
  if (with_c) {
    g.add_edge(0, 2);
    g.add_edge(2, 1);
  }
  g.finish();
  return g;
}

TEST(GeometricGraph, PathsStayWithinTheArcsValuesThenBelowItsTop) {
  GeometricGraph::Search scratch;
  // Within [0, 1]: through c.
  const GeometricGraph within = diamond(true);
  const std::vector<Vec3> expect_c = {{0, 0, 0}, {0.5, 1, 0}, {1, 0, 0}};
  EXPECT_EQ(within.path(0, 1, scratch), expect_c);
  // No path within [0, 1]: below b's value, through d and its edges' points (not through e,
  // which a search for any path finds first).
  const GeometricGraph below = diamond(false);
  const std::vector<Vec3> expect_d = {
      {0, 0, 0}, {0.2, -1, 0}, {0.5, -1, 0}, {0.8, -1, 0}, {1, 0, 0}};
  EXPECT_EQ(below.path(0, 1, scratch), expect_d);
  // From b to a: the same nodes, reversed.
  EXPECT_EQ(below.path(1, 0, scratch), std::vector<Vec3>(expect_d.rbegin(), expect_d.rend()));
  // A fresh scratch gives the same path; the first, used on another graph since, still serves.
  GeometricGraph::Search fresh;
  EXPECT_EQ(below.path(0, 1, fresh), expect_d);
  EXPECT_EQ(within.path(0, 1, scratch), expect_c);
}

TEST(GeometricGraph, AnyPathWhenNoneBelowTheTop) {
  // a (0) and b (1) joined only through e (5): any path, rather than a chord.
  GeometricGraph g({{0, 0, 0}, {1, 0, 0}, {0.5, 2, 0}}, {0.0, 1.0, 5.0});
  g.add_edge(0, 2);
  g.add_edge(2, 1);
  g.finish();
  const std::vector<Vec3> expect = {{0, 0, 0}, {0.5, 2, 0}, {1, 0, 0}};
  GeometricGraph::Search scratch;
  EXPECT_EQ(g.path(0, 1, scratch), expect);
  // Not connected at all: the chord.
  GeometricGraph apart({{0, 0, 0}, {1, 0, 0}}, {0.0, 1.0});
  apart.finish();
  EXPECT_EQ(apart.path(0, 1, scratch), (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}));
}

TEST(GeometricGraph, ForestPathsFollowEachGraphsOwnEdges) {
  // a (0) and b (1) joined through e (5) above them in g; a copy of g taken before finish()
  // also joins them through d (-1) below. With no search below (below_visits 0), the forests'
  // paths: in g the superlevel forest's, through e (the sublevel one's passes e too, above b);
  // in the copy the sublevel forest's through d (as short as the one through e, and preferred),
  // from forests of its own edges even after g's were built.
  GeometricGraph g({{0, 0, 0}, {1, 0, 0}, {0.5, -1, 0}, {0.5, 2, 0}}, {0.0, 1.0, -1.0, 5.0});
  g.add_edge(0, 3);
  g.add_edge(3, 1);
  GeometricGraph copy = g;
  copy.add_edge(0, 2);
  copy.add_edge(2, 1);
  g.finish();
  copy.finish();
  GeometricGraph::Search scratch;
  EXPECT_EQ(g.path(0, 1, scratch, 0), (std::vector<Vec3>{{0, 0, 0}, {0.5, 2, 0}, {1, 0, 0}}));
  EXPECT_EQ(copy.path(0, 1, scratch, 0), (std::vector<Vec3>{{0, 0, 0}, {0.5, -1, 0}, {1, 0, 0}}));
}

TEST(GeometricGraph, LongPathsKeepEveryEdgesPointsInOrder) {
  // A chain of 21 nodes, its edges added in alternating directions, each with an interior point
  // listed in its own direction: the path between the chain's ends (the two searches meet in
  // the middle) is the whole chain with every point in order, either way.
  const int n = 21;
  std::vector<Vec3> nodes;
  std::vector<double> values;
  for (int i = 0; i < n; ++i) {
    nodes.push_back({double(i), 0, 0});
    values.push_back(double(i) / (n - 1));
  }
  GeometricGraph chain(nodes, values);
  std::vector<Vec3> expect;
  for (int i = 0; i + 1 < n; ++i) {
    const Vec3 mid = {i + 0.5, 0.1 * i, 0};
    if (i % 2 == 0)
      chain.add_edge(i, i + 1, std::vector<Vec3>{mid});
    else
      chain.add_edge(i + 1, i, std::vector<Vec3>{mid});
    expect.push_back(nodes[i]);
    expect.push_back(mid);
  }
  expect.push_back(nodes[n - 1]);
  chain.finish();
  GeometricGraph::Search scratch;
  EXPECT_EQ(chain.path(0, n - 1, scratch), expect);
  EXPECT_EQ(chain.path(n - 1, 0, scratch), std::vector<Vec3>(expect.rbegin(), expect.rend()));
  // From the middle to an end, and a node to itself.
  EXPECT_EQ(chain.path(10, n - 1, scratch), std::vector<Vec3>(expect.begin() + 20, expect.end()));
  EXPECT_EQ(chain.path(7, 7, scratch), std::vector<Vec3>{nodes[7]});
}

TEST(GeometricGraph, EdgesSetAtOnceGiveTheSamePaths) {
  // The diamond without c, its edges given at once (with an edge from d to itself, left out of
  // the adjacency) instead of one by one: the same path below b, the same points.
  GeometricGraph g({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 2, 0}},
                   {0.0, 1.0, 0.5, -1.0, 5.0});
  UninitializedVector<Vec3> points;
  for (const Vec3 &p :
       {Vec3{0.2, 1, 0}, Vec3{0.8, 1, 0}, Vec3{0.2, -1, 0}, Vec3{9, 9, 9}, Vec3{0.8, -1, 0}})
    points.push_back(p);
  g.set_edges({{0, 4}, {4, 1}, {0, 3}, {3, 3}, {3, 1}}, {0, 1, 2, 3, 4, 5}, std::move(points));
  g.finish();
  GeometricGraph::Search scratch;
  EXPECT_EQ(g.path(0, 1, scratch), diamond(false).path(0, 1, scratch));
  const std::vector<Vec3> expect_d = {
      {0, 0, 0}, {0.2, -1, 0}, {0.5, -1, 0}, {0.8, -1, 0}, {1, 0, 0}};
  EXPECT_EQ(g.path(0, 1, scratch), expect_d);
}

TEST(GeometricGraph, PathsAreWalksThroughTheGraphWithinTheValues) {
  // A 40 x 40 grid with a fifth of its edges missing and random values: every path between
  // random pairs of nodes in one piece steps from node to adjacent node, stays within the two
  // ends' values when it can (checked against a plain search of the nodes within them), and
  // otherwise below the upper end's value or above the lower's (both seen).
  const int side = 40;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> nodes;
  std::vector<double> values;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      nodes.push_back({double(x), double(y), 0});
      values.push_back(u(rng));
    }
  GeometricGraph g(nodes, values);
  std::vector<std::vector<int>> adjacent(nodes.size());
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      for (auto [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (x + dx >= side || y + dy >= side || u(rng) < 0.2)
          continue;
        const int a = y * side + x, b = (y + dy) * side + x + dx;
        g.add_edge(a, b);
        adjacent[a].push_back(b);
        adjacent[b].push_back(a);
      }
  g.finish();
  // Nodes reachable from a through nodes within [lo, hi] (a plain breadth-first search).
  auto reachable = [&](int a, double lo, double hi) {
    std::vector<char> seen(nodes.size(), 0);
    std::vector<int> queue = {a};
    seen[a] = 1;
    for (std::size_t q = 0; q < queue.size(); ++q)
      for (int w : adjacent[queue[q]])
        if (!seen[w] && values[w] >= lo && values[w] <= hi) {
          seen[w] = 1;
          queue.push_back(w);
        }
    return seen;
  };
  auto node_at = [&](const Vec3 &p) { return int(p[1]) * side + int(p[0]); };
  GeometricGraph::Search scratch;
  int within = 0, below = 0, above = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int a = int(u(rng) * nodes.size()), b = int(u(rng) * nodes.size());
    const double lo = std::min(values[a], values[b]), hi = std::max(values[a], values[b]);
    const bool can_within = reachable(a, lo, hi)[b];
    const bool can_below = reachable(a, -INFINITY, hi)[b],
               can_above = reachable(a, lo, INFINITY)[b];
    if (!can_below && !can_above)
      continue;
    const std::vector<Vec3> p = g.path(a, b, scratch);
    ASSERT_GE(p.size(), 1u);
    EXPECT_EQ(node_at(p.front()), a);
    EXPECT_EQ(node_at(p.back()), b);
    double path_lo = INFINITY, path_hi = -INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const int v = node_at(p[i]);
      path_lo = std::min(path_lo, values[v]);
      path_hi = std::max(path_hi, values[v]);
      if (i > 0) {
        const int w = node_at(p[i - 1]);
        EXPECT_NE(std::find(adjacent[v].begin(), adjacent[v].end(), w), adjacent[v].end())
            << "step " << i << " of the path from " << a << " to " << b;
      }
    }
    if (can_within) {
      EXPECT_GE(path_lo, lo);
      EXPECT_LE(path_hi, hi);
      ++within;
    } else {
      EXPECT_TRUE(path_hi <= hi || path_lo >= lo) << a << " to " << b;
      EXPECT_FALSE(path_hi <= hi && path_lo >= lo) << "a path within the values, found late";
      below += path_hi <= hi;
      above += path_lo >= lo;
    }
  }
  EXPECT_GT(within, 10);
  EXPECT_GT(below, 10);
  EXPECT_GT(above, 10);
}

} // namespace
} // namespace hoct
