// Two trees (or Reeb graphs) of one mesh computed two ways, compared: nodes bit for bit (type,
// value, cell, (u, v), position, location, fallback), arcs, persistence pairs and the exact
// pipeline's counts.
#pragma once

#include "tree/tree_result.hpp"

#include <gtest/gtest.h>

#include <string>

namespace hoct::testing {

// Nodes, arcs and persistence pairs.
inline void expect_same_graph(const TreeResult &a, const TreeResult &b, const std::string &what) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size()) << what;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const TreeNode &x = a.nodes[i], &y = b.nodes[i];
    EXPECT_EQ(x.type, y.type) << what << " node " << i;
    EXPECT_EQ(x.value, y.value) << what << " node " << i;
    EXPECT_EQ(x.cell, y.cell) << what << " node " << i;
    EXPECT_EQ(x.uv, y.uv) << what << " node " << i;
    EXPECT_EQ(x.position, y.position) << what << " node " << i;
    EXPECT_EQ(x.location, y.location) << what << " node " << i;
    EXPECT_EQ(x.fallback, y.fallback) << what << " node " << i;
  }
  EXPECT_EQ(a.arcs, b.arcs) << what;
  ASSERT_EQ(a.pairs.size(), b.pairs.size()) << what;
  for (std::size_t i = 0; i < a.pairs.size(); ++i) {
    EXPECT_EQ(a.pairs[i].birth, b.pairs[i].birth) << what;
    EXPECT_EQ(a.pairs[i].death, b.pairs[i].death) << what;
  }
}

// The same and the exact pipeline's counts.
inline void expect_same_tree(const TreeResult &a, const TreeResult &b, const std::string &what) {
  expect_same_graph(a, b, what);
  if (::testing::Test::HasFatalFailure())
    return;
  ASSERT_TRUE(a.stats.exact && b.stats.exact) << what;
  const ExactCounts &p = *a.stats.exact, &q = *b.stats.exact;
  EXPECT_EQ(p.cells, q.cells) << what;
  EXPECT_EQ(p.graph_nodes, q.graph_nodes) << what;
  EXPECT_EQ(p.edge_critical_points, q.edge_critical_points) << what;
  EXPECT_EQ(p.interior_critical_points, q.interior_critical_points) << what;
  EXPECT_EQ(p.connections_direct, q.connections_direct) << what;
  EXPECT_EQ(p.connections_traced, q.connections_traced) << what;
  EXPECT_EQ(p.fallback_cells, q.fallback_cells) << what;
  EXPECT_EQ(p.fallback_by_reason, q.fallback_by_reason) << what;
  EXPECT_EQ(p.fallback_error, q.fallback_error) << what;
  EXPECT_EQ(p.fallback_arcs_contracted, q.fallback_arcs_contracted) << what;
}

} // namespace hoct::testing
