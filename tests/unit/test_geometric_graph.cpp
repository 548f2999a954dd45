// The geometric graph's arc paths: within the arc's values where the graph allows it, else below
// the upper end's value (where the join tree connects an arc's ends), else any path; one scratch
// serves searches on different graphs.
#include "tree/geometric_graph.hpp"

#include <gtest/gtest.h>

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

} // namespace
} // namespace hoct
