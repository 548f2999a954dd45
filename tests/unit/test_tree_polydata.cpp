// io/tree_polydata: the layout of a tree as PolyData (nodes first, then the interior points of
// the arcs' polylines), on a small tree built by hand.
#include "io/tree_polydata.hpp"

#include <gtest/gtest.h>

namespace hoct {
namespace {

// minimum (0) - saddle (1) - maximum (2), and a second maximum (3) on the saddle.
TreeResult small_tree() {
  TreeResult t;
  const NodeType types[4] = {NodeType::Minimum, NodeType::Saddle, NodeType::Maximum,
                             NodeType::Maximum};
  const double values[4] = {0, 1, 4, 2};
  for (int i = 0; i < 4; ++i) {
    TreeNode n;
    n.type = types[i];
    n.value = values[i];
    n.position = {double(i), 0, 0};
    n.cell = 10 + i;
    n.location = NodeLocation::Interior;
    n.fallback = i == 3;
    t.nodes.push_back(n);
  }
  t.arcs = {{0, 1}, {1, 2}, {1, 3}};
  t.pairs = {{PersistencePair::Kind::Split, 3, 1, 2, 1},
             {PersistencePair::Kind::Global, 0, 2, 0, 4}};
  return t;
}

TEST(TreePolyData, StraightArcs) {
  const TreePolyData d = tree_polydata(small_tree());
  ASSERT_EQ(d.num_nodes, 4u);
  ASSERT_EQ(d.num_points(), 4u);
  EXPECT_EQ(d.line_connectivity, (std::vector<int64_t>{0, 1, 1, 2, 1, 3}));
  EXPECT_EQ(d.line_offsets, (std::vector<int64_t>{2, 4, 6}));
  EXPECT_EQ(d.type[1], NodeType::Saddle);
  EXPECT_EQ(d.points[3 * 2], 2.0);
  // Node persistence: the largest pair a node is in; arc persistence: the smaller end's.
  EXPECT_EQ(d.persistence, (std::vector<double>{4, 1, 4, 1}));
  EXPECT_EQ(d.arc_persistence, (std::vector<double>{1, 1, 1}));
  EXPECT_EQ(d.cell[3], 13);
  EXPECT_EQ(d.fallback, (std::vector<uint8_t>{0, 0, 0, 1}));
}

TEST(TreePolyData, PolylinesFollowTheNodes) {
  TreeResult t = small_tree();
  t.arc_paths = {{{0, 0, 0}, {0.5, 1, 0}, {1, 0, 0}},
                 {{1, 0, 0}, {2, 0, 0}},
                 {{1, 0, 0}, {1.5, 1, 0}, {2, 1, 0}, {3, 0, 0}}};
  const TreePolyData d = tree_polydata(t);
  ASSERT_EQ(d.num_points(), 4u + 1 + 0 + 2);
  EXPECT_EQ(d.line_connectivity, (std::vector<int64_t>{0, 4, 1, 1, 2, 1, 5, 6, 3}));
  EXPECT_EQ(d.line_offsets, (std::vector<int64_t>{3, 5, 9}));
  EXPECT_EQ(d.points[3 * 5 + 1], 1.0);
  // Values interpolated along the polyline (by index), other attributes of "no node".
  EXPECT_DOUBLE_EQ(d.value[4], 0.5);
  EXPECT_DOUBLE_EQ(d.value[5], 1 + 1.0 / 3);
  EXPECT_DOUBLE_EQ(d.value[6], 1 + 2.0 / 3);
  EXPECT_EQ(d.node_id[5], -1);
  EXPECT_EQ(d.type[5], NodeType::Regular);
  EXPECT_EQ(d.persistence[6], 1.0);
}

} // namespace
} // namespace hoct
