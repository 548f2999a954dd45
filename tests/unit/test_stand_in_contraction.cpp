// The contraction of the fallback stand-in's short arcs (tree/stand_in_contraction.hpp), on
// graphs whose result is known by hand: a ridge the stand-in broke into two maxima becomes one,
// and a Reeb graph's loop made of stand-in nodes within the slack is kept whole (its arcs are
// never contracted: parallel arcs leave neither end with a single arc on that side), with no
// arc from a node to itself.
#include "tree/contour_tree.hpp"
#include "tree/stand_in_contraction.hpp"

#include "test_graphs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace hoct {
namespace {

TEST(StandInContraction, ABrokenRidgeIsOneMaximum) {
  // Maxima 2 (0.99) and 3 (1.0) joined at saddle 1 (0.97), all the stand-in's (slack 0.05): the
  // arc 1-2 (0.02) is contracted, 1 left regular is spliced out: the minimum and one maximum.
  const ContourTree g = testing::graph_of({0, 0.97, 0.99, 1.0}, {{0, 1}, {1, 2}, {1, 3}});
  const StandInContraction c = contract_stand_in_arcs(g, {-1, 0.05, 0.05, 0.05});
  EXPECT_EQ(c.contracted, 1);
  EXPECT_EQ(c.tree.nodes, (std::vector<int64_t>{0, 3}));
  EXPECT_EQ(c.tree.arcs, (std::vector<std::array<int64_t, 2>>{{0, 1}}));
  // Beyond twice the slack nothing moves.
  EXPECT_EQ(contract_stand_in_arcs(g, {-1, 0.005, 0.005, 0.005}).contracted, 0);
}

TEST(StandInContraction, ALoopWithinTheSlackIsKept) {
  // Two parallel arcs between stand-in nodes 1 and 2 (a loop of persistence 0.05).
  const ContourTree two = testing::graph_of({0, 1, 1.05, 2}, {{0, 1}, {1, 2}, {1, 2}, {2, 3}});
  const StandInContraction a = contract_stand_in_arcs(two, {-1, 0.1, 0.1, -1});
  EXPECT_EQ(a.contracted, 0);
  EXPECT_EQ(a.tree.arcs, two.arcs);
  EXPECT_EQ(graph_loops(a.tree), 1);
  // A triangle 1-2-3 of stand-in nodes: the arc 1-2 contracted (2 has one arc down) makes the
  // loop two parallel arcs 1-3, which stay.
  const ContourTree tri =
      testing::graph_of({0, 1, 1.02, 1.04, 2}, {{0, 1}, {1, 2}, {1, 3}, {2, 3}, {3, 4}});
  const StandInContraction b = contract_stand_in_arcs(tri, {-1, 0.1, 0.1, 0.1, -1});
  EXPECT_EQ(b.contracted, 1);
  EXPECT_EQ(graph_loops(b.tree), 1);
  for (const auto &arc : b.tree.arcs)
    EXPECT_NE(arc[0], arc[1]);
  EXPECT_EQ(b.tree.nodes, (std::vector<int64_t>{0, 1, 3, 4}));
}

} // namespace
} // namespace hoct
