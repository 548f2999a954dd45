// Gluing along given routes (tree/path_gluing.hpp), as a Reeb graph glued in stages needs them
// (exact/reeb_group): on a graph with a loop the route says which side a curve runs along, and
// the result follows it; on a forest the routes of its own paths give what the path search
// gives; each input node and arc is found again in the glued graph.
#include "tree/path_gluing.hpp"

#include "test_graphs.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace hoct {
namespace {

using Arcs = std::vector<std::array<int64_t, 2>>;

// A loop a (0) - b (3), one side the arc a-b, the other through m (1.5); beside it a tree c (0) -
// s (1) - d (3). The curve c-d is glued to a-b, along one side or the other.
//   nodes: 0 a, 1 c, 2 s, 3 m, 4 b, 5 d
//   arcs (sorted): 0 a-m, 1 a-b, 2 c-s, 3 s-d, 4 m-b
ContourTree loop_and_tree() {
  return testing::graph_of({0, 0, 1, 1.5, 3, 3}, {{0, 3}, {0, 4}, {1, 2}, {2, 5}, {3, 4}});
}

PathGluing along(std::vector<int64_t> side) {
  PathGluing g;
  g.paths.push_back({0, 4, 1, 5});
  g.routes.push_back({std::move(side), {2, 3}});
  return g;
}

TEST(PathGluing, ARouteChoosesTheSideOfALoop) {
  const ContourTree loop = loop_and_tree();
  // Along the arc a-b: it is cut at s's level; a, s, m, b with a-s, s-b, and the side a-m-b.
  const GluedGraph direct = glue_paths(loop, along({1}), false);
  EXPECT_EQ(direct.graph.nodes, (std::vector<int64_t>{0, 2, 3, 4}));
  EXPECT_EQ(direct.graph.arcs, (Arcs{{0, 1}, {0, 2}, {1, 3}, {2, 3}}));
  EXPECT_EQ(direct.node_of, (std::vector<int64_t>{0, 0, 1, 2, 3, 3}));
  // a-m stays whole; a-b and c-s-d are glued into a-s, s-b.
  EXPECT_EQ(direct.arc_image, (std::vector<std::vector<int64_t>>{{1}, {0, 2}, {0}, {2}, {3}}));
  // Along a-m-b: a-m cut at s's level, s-d at m's; a-s, s-m, m-b glued, a-b apart.
  const GluedGraph round = glue_paths(loop, along({0, 4}), false);
  EXPECT_EQ(round.graph.nodes, (std::vector<int64_t>{0, 2, 3, 4}));
  EXPECT_EQ(round.graph.arcs, (Arcs{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
  EXPECT_EQ(round.arc_image, (std::vector<std::vector<int64_t>>{{0, 2}, {1}, {0}, {2, 3}, {3}}));
  EXPECT_EQ(graph_loops(direct.graph), 1);
  EXPECT_EQ(graph_loops(round.graph), 1);
}

TEST(PathGluing, ARouteThatLeavesItsArcsOrEndsElsewhereIsRefused) {
  const ContourTree loop = loop_and_tree();
  EXPECT_THROW(glue_paths(loop, along({4})), std::invalid_argument); // m-b does not start at a
  EXPECT_THROW(glue_paths(loop, along({0})), std::invalid_argument); // ends at m, not b
  EXPECT_THROW(glue_paths(loop, along({9})), std::invalid_argument); // no such arc
  PathGluing two = along({1});
  two.paths.push_back(two.paths.front());
  EXPECT_THROW(glue_paths(loop, two), std::invalid_argument); // one route for two paths
}

// A random forest of two trees, the second a copy of the first (interleaved: node 2k and its
// copy 2k + 1), each node above its parent; paths from an ancestor up to a node glued to the
// copy's. With the routes the forest's own paths (forest_paths), the gluing is the one that
// searches them.
TEST(PathGluing, OnAForestRoutesOfItsPathsGiveWhatTheSearchGives) {
  std::mt19937 rng(7);
  for (int round = 0; round < 50; ++round) {
    const int n = 2 + static_cast<int>(rng() % 30);
    std::vector<int64_t> parent(n, -1);
    std::vector<double> values;
    Arcs arcs;
    for (int k = 0; k < n; ++k) {
      values.push_back(k);
      values.push_back(k);
      if (k > 0) {
        parent[k] = static_cast<int64_t>(rng() % k);
        arcs.push_back({2 * parent[k], 2 * k});
        arcs.push_back({2 * parent[k] + 1, 2 * k + 1});
      }
    }
    const ContourTree forest = testing::graph_of(values, arcs);
    PathGluing searched;
    std::vector<std::array<int64_t, 2>> ends;
    for (int p = 0; p < 1 + static_cast<int>(rng() % 5); ++p) {
      int64_t top = static_cast<int64_t>(rng() % n), low = top;
      for (int up = static_cast<int>(rng() % 4); up > 0 && parent[low] >= 0; --up)
        low = parent[low];
      if (low == top)
        continue;
      searched.paths.push_back({2 * low, 2 * top, 2 * low + 1, 2 * top + 1});
      ends.push_back({2 * low, 2 * top});
      ends.push_back({2 * low + 1, 2 * top + 1});
    }
    PathGluing routed = searched;
    const std::vector<std::vector<int64_t>> paths = forest_paths(forest, ends);
    for (std::size_t p = 0; p < searched.paths.size(); ++p)
      routed.routes.push_back({paths[2 * p], paths[2 * p + 1]});
    for (bool reduced : {false, true}) {
      const GluedGraph a = glue_paths(forest, searched, reduced),
                       b = glue_paths(forest, routed, reduced);
      EXPECT_EQ(a.graph.nodes, b.graph.nodes) << round;
      EXPECT_EQ(a.graph.arcs, b.graph.arcs) << round;
    }
  }
}

} // namespace
} // namespace hoct
