// Removing a Reeb graph's loops below a threshold (tree/loop_removal.hpp): graphs whose loops and
// collapses are known by hand, and a generated plate with holes, whose simplified graph keeps
// exactly the loops whose essential pair reaches the threshold.
#include "datasets/datasets.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"
#include "tree/loop_pairs.hpp"
#include "tree/loop_removal.hpp"
#include "tree/simplification.hpp"

#include "test_graphs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace hoct {
namespace {

std::vector<double> loop_persistences(const ContourTree &g) {
  std::vector<double> p;
  for (const PersistencePair &x : loop_pairs(g))
    p.push_back(x.persistence());
  std::sort(p.begin(), p.end());
  return p;
}

// Two loops made of parallel arcs: 1-2 (persistence 1) and 3-4 (persistence 1.5).
ContourTree two_loops() {
  return testing::graph_of({0, 1, 2, 5, 6.5, 10},
                           {{0, 1}, {1, 2}, {1, 2}, {2, 3}, {3, 4}, {3, 4}, {4, 5}});
}

TEST(LoopRemoval, TheSmallerLoopGoesFirst) {
  const ContourTree g = two_loops();
  ASSERT_EQ(loop_persistences(g), (std::vector<double>{1, 1.5}));
  const LoopRemoval none = remove_loops(g, 0.5);
  EXPECT_EQ(none.removed, 0);
  EXPECT_EQ(none.graph.arcs, g.arcs);
  const LoopRemoval one = remove_loops(g, 1.2);
  EXPECT_EQ(one.removed, 1);
  // Nodes 1 and 2 became regular on the collapsed chain: spliced out.
  EXPECT_EQ(one.kept, (std::vector<int64_t>{0, 3, 4, 5}));
  EXPECT_EQ(one.graph.arcs, (std::vector<std::array<int64_t, 2>>{{0, 1}, {1, 2}, {1, 2}, {2, 3}}));
  EXPECT_EQ(loop_persistences(one.graph), (std::vector<double>{1.5}));
  const LoopRemoval both = remove_loops(g, 2);
  EXPECT_EQ(both.removed, 2);
  EXPECT_EQ(both.kept, (std::vector<int64_t>{0, 5}));
  EXPECT_EQ(both.graph.arcs, (std::vector<std::array<int64_t, 2>>{{0, 1}}));
}

TEST(LoopRemoval, ALoopWithBranchesCollapsesToOneChain) {
  // The loop 2-3-5-4-2 (bottom 2 at 1, top 5 at 3: persistence 2); node 3 has a maximum 6 above
  // it, node 4 a minimum 1 below it. Collapsed, its nodes in value order form one chain
  // 2-3-4-5; 2 and 5 become regular, 3 stays an up-fork and 4 a down-fork: a tree.
  const ContourTree g =
      testing::graph_of({0, 0.5, 1, 2, 2.5, 3, 3.5, 5},
                        {{0, 2}, {2, 3}, {2, 4}, {1, 4}, {3, 5}, {4, 5}, {3, 6}, {5, 7}});
  ASSERT_EQ(loop_persistences(g), (std::vector<double>{2}));
  EXPECT_EQ(remove_loops(g, 2).removed, 0); // below, not at
  const LoopRemoval r = remove_loops(g, 2.5);
  EXPECT_EQ(r.removed, 1);
  EXPECT_EQ(r.kept, (std::vector<int64_t>{0, 1, 3, 4, 6, 7}));
  // Indices of the kept nodes: 0 -> 0, 1 -> 1, 3 -> 2, 4 -> 3, 6 -> 4, 7 -> 5.
  EXPECT_EQ(r.graph.arcs,
            (std::vector<std::array<int64_t, 2>>{{0, 2}, {1, 3}, {2, 3}, {2, 4}, {3, 5}}));
  EXPECT_EQ(graph_loops(r.graph), 0);
  // The simplification with loops: the same graph, then its leaves pruned as on a tree.
  const Simplification s = simplify(g, 2.5, true);
  EXPECT_EQ(s.removed_loops, 1);
  EXPECT_EQ(graph_loops(s.tree), 0);
  const Simplification kept = simplify(g, 2.5);
  EXPECT_EQ(kept.removed_loops, 0);
  EXPECT_EQ(graph_loops(kept.tree), 1); // leaves pruned, the loop kept
}

// A plate with holes: the Reeb graph's loops whose essential pair is below the threshold go, the
// others stay; the graph stays a Reeb graph (sum of (degree - 2) = 2 (loops - components)).
TEST(LoopRemoval, APlateKeepsTheLoopsAboveTheThreshold) {
  const MeshInput in = generate_dataset("plate", {});
  const Mesh mesh = build_mesh(in);
  const TreeResult whole = compute_tree(mesh, TreeRequest{}, &in).tree;
  std::vector<double> loops;
  for (const PersistencePair &p : whole.pairs)
    if (p.kind == PersistencePair::Kind::Loop)
      loops.push_back(p.persistence());
  ASSERT_GE(loops.size(), 2u);
  ASSERT_EQ(static_cast<int64_t>(loops.size()), whole.loops);
  std::sort(loops.begin(), loops.end());
  // Between the smallest and the largest loop.
  const double threshold = 0.5 * (loops.front() + loops.back());
  const auto above =
      std::count_if(loops.begin(), loops.end(), [&](double p) { return p >= threshold; });
  ASSERT_GT(above, 0);
  ASSERT_LT(above, static_cast<std::ptrdiff_t>(loops.size()));
  for (bool with_loops : {false, true}) {
    SCOPED_TRACE(with_loops ? "loops removed" : "loops kept");
    TreeRequest rq;
    rq.simplify = Threshold{threshold, false};
    rq.simplify_loops = with_loops;
    const TreeResult t = *compute_tree(mesh, rq, &in).simplified;
    EXPECT_EQ(t.loops, with_loops ? above : whole.loops);
    ASSERT_TRUE(t.stats.loops_removed.has_value() == with_loops);
    if (with_loops) {
      EXPECT_EQ(*t.stats.loops_removed, whole.loops - above);
    }
    int64_t excess = 0;
    for (const TreeNode &n : t.nodes)
      excess += n.up + n.down - 2;
    EXPECT_EQ(excess, 2 * (t.loops - 1));
    int64_t loop_pairs_left = 0;
    for (const PersistencePair &p : t.pairs)
      if (p.kind == PersistencePair::Kind::Loop) {
        ++loop_pairs_left;
        if (with_loops) {
          EXPECT_GE(p.persistence(), threshold);
        }
      }
    EXPECT_EQ(loop_pairs_left, t.loops);
  }
}

} // namespace
} // namespace hoct
