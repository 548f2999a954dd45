// Level edges: constant mesh edges across which the field rises or falls (a Dirichlet boundary,
// a field of one coordinate on a structured mesh, a kink of a C0 field along mesh edges). They
// hold no critical point and need no fallback; the trees are known by hand, and the PL trees of
// refinements converge to them.
#include "cell/level_edges.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"
#include "test_meshes.hpp"
#include "test_refinement_convergence.hpp"
#include "test_tree_shape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace hoct {
namespace {

TreeResult tree_of(const MeshInput &in) {
  const Mesh mesh = build_mesh(in);
  return compute_tree(mesh, TreeRequest{}, &in).tree;
}

// The exact tree of `in`, checked: its shape, its nodes' values (ascending), no fallback cell, and
// the PL trees of refinements converging to it.
TreeResult certified_tree(const MeshInput &in, const std::string &shape,
                          const std::vector<double> &values) {
  const Mesh mesh = build_mesh(in);
  TreeResult t = compute_tree(mesh, TreeRequest{}, &in).tree;
  EXPECT_EQ(testing::tree_shape(t), shape);
  EXPECT_EQ(t.nodes.size(), values.size());
  for (std::size_t i = 0; i < std::min(t.nodes.size(), values.size()); ++i)
    EXPECT_NEAR(t.nodes[i].value, values[i], 1e-12) << "node " << i;
  EXPECT_TRUE(t.stats.exact && t.stats.exact->fallback_cells == 0);
  testing::expect_refinements_converge(mesh, in, t);
  return t;
}

// y (1 - y) (1 + x / 2): zero on the bottom and top sides (Dirichlet), rising into the square
// from both; no interior critical point. The two sides are minima, joined at the left side's
// middle (0, 0.5) at 0.25; the maximum is the right side's middle (1, 0.5) at 0.375.
double dirichlet(double x, double y) { return y * (1 - y) * (1 + x / 2); }

TEST(LevelEdges, DirichletSidesAreMinimaWithoutFallback) {
  const TreeResult t =
      certified_tree(testing::lattice_grid(4, 3, dirichlet),
                     "minimum(0,1) minimum(0,1) saddle(2,1) maximum(1,0)", {0, 0, 0.25, 0.375});
  ASSERT_EQ(t.nodes.size(), 4u);
  EXPECT_NEAR(t.nodes[2].position[0], 0, 1e-12);
  EXPECT_NEAR(t.nodes[2].position[1], 0.5, 1e-12);
  EXPECT_EQ(t.stats.exact->level_edges, 8); // four on each of the two sides, one cell each
}

TEST(LevelEdges, AnOffsetKeepsThemLevel) {
  // The same field at 1e5 (kelvin, pascal): the same tree and the same certificates.
  const TreeResult t = tree_of(
      testing::lattice_grid(4, 3, [](double x, double y) { return 1e5 + dirichlet(x, y); }));
  EXPECT_EQ(testing::tree_shape(t), "minimum(0,1) minimum(0,1) saddle(2,1) maximum(1,0)");
  ASSERT_EQ(t.nodes.size(), 4u);
  EXPECT_NEAR(t.nodes[2].value, 1e5 + 0.25, 1e-9);
  ASSERT_TRUE(t.stats.exact);
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
  EXPECT_EQ(t.stats.exact->level_edges, 8);
}

TEST(LevelEdges, DirichletSidesMeetingAtACriticalCorner) {
  // x y (3 - x - y) (P3): zero on the bottom and left sides, whose normal derivatives vanish at
  // the corner (0, 0), a critical point (the gradient is zero there). The two cells at that
  // corner (split by the diagonal) rise from their side everywhere but there: certified, the
  // corner counted as critical. The sides are one minimum, the corner (1, 1) the maximum (1).
  const TreeResult t = certified_tree(
      testing::lattice_grid(4, 3, [](double x, double y) { return x * y * (3 - x - y); }),
      "minimum(0,1) maximum(1,0)", {0, 1});
  EXPECT_GE(t.stats.exact->critical_corners, 2);
}

TEST(LevelEdges, AKinkAlongMeshEdgesIsOneMinimum) {
  // |x - 0.5| (linear in each cell, held as P2): every vertical edge is constant, the field
  // rising from x = 0.5 on both sides. The kink is the minimum, each side x = 0, x = 1 a maximum.
  const TreeResult t = certified_tree(
      testing::lattice_grid(4, 2, [](double x, double) { return std::abs(x - 0.5); }),
      "minimum(0,2) maximum(1,0) maximum(1,0)", {0, 0.5, 0.5});
  EXPECT_EQ(t.stats.exact->level_edges, 32); // 12 inner vertical edges twice, 8 on the sides
}

TEST(LevelEdges, AnEdgeWhereTheGradientVanishesIsNone) {
  // (x - 0.5)^2: the vertical edges at x = 0.5 are a valley (zero gradient), not level edges;
  // the others are.
  const MeshInput in =
      testing::lattice_grid(4, 2, [](double x, double) { return (x - 0.5) * (x - 0.5); });
  const Mesh mesh = build_mesh(in);
  int64_t level = 0, constant = 0;
  for (int64_t e = 0; e < mesh.topology.num_edges(); ++e) {
    const auto &ev = mesh.topology.edge_vertices(e);
    const double x0 = in.points[static_cast<std::size_t>(mesh.topology.vertex_point(ev[0]))][0];
    const double x1 = in.points[static_cast<std::size_t>(mesh.topology.vertex_point(ev[1]))][0];
    if (x0 != x1)
      continue;
    ++constant;
    for (int j = 0; j < mesh.topology.edge_cell_count(e); ++j) {
      const int64_t c = mesh.topology.edge_cells_begin(e)[j];
      const bool is = is_level_edge(mesh.field.cell_polynomial(c), mesh.topology.local_edge(c, e),
                                    mesh.field.precision());
      EXPECT_EQ(is, x0 != 0.5) << "edge at x = " << x0;
      level += is;
    }
  }
  EXPECT_EQ(constant, 20);
  EXPECT_EQ(level, 24); // 8 inner edges on both sides, 8 on the square's sides
}

} // namespace
} // namespace hoct
