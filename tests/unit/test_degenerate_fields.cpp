// Degenerate fields (issue 8): constant fields, plateaus, saddles exactly on vertices and edges,
// monkey saddles, ties, non-finite, huge and tiny values. Each gives a tree that passes the
// invariant checker (analysis/tree_check.hpp) or a clear hoct::Error.
#include "analysis/tree_check.hpp"
#include "cell/edge_nodes.hpp"
#include "exact/exact_contour_tree.hpp"
#include "mesh/mesh.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/refinement.hpp"
#include "test_meshes.hpp"
#include "tree/persistence.hpp"
#include "util/error.hpp"

#include "cell/edge_nodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hoct {
namespace {

using Fn = std::function<double(const Vec3 &)>;

// An n x n grid on [-1, 1]^2 (shifted by (dx, dy)), unjittered, degree d, values f(position).
MeshInput grid_input(int n, int d, const Fn &f, double dx = 0, double dy = 0) {
  std::mt19937_64 rng(5);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      verts.push_back({-1 + 2.0 * i / n + dx, -1 + 2.0 * j / n + dy, 0.0});
  auto id = [&](int i, int j) { return static_cast<int64_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return testing::lagrange_mesh(
      verts, tris, [&](int64_t) { return d; }, {}, f, rng, false);
}

TreeResult checked_tree(const Mesh &m) {
  const TreeResult t = contract_flat(exact_contour_tree(m));
  const TreeCheckReport r = check_tree(t, m);
  EXPECT_TRUE(r.ok()) << r.summary();
  return t;
}

const TreeNode *node_at(const TreeResult &t, double x, double y) {
  for (const auto &n : t.nodes)
    if (std::hypot(n.position[0] - x, n.position[1] - y) < 1e-9)
      return &n;
  return nullptr;
}

TEST(DegenerateFields, ConstantFieldIsOneNode) {
  for (int d : {1, 3}) {
    const Mesh m = build_mesh(grid_input(4, d, [](const Vec3 &) { return 2.5; }));
    const TreeResult t = checked_tree(m);
    EXPECT_EQ(t.nodes.size(), 1u);
    EXPECT_TRUE(t.arcs.empty());
    EXPECT_DOUBLE_EQ(t.nodes[0].value, 2.5);
  }
}

TEST(DegenerateFields, PlateauIsOneNode) {
  // min(x, 0) with linear cells: the half x >= 0 is a plateau at the maximum value 0; the
  // vertical edges left of it are level edges, x = 0 too (seen from the left).
  const Mesh m = build_mesh(grid_input(6, 1, [](const Vec3 &p) { return std::min(p[0], 0.0); }));
  const TreeResult t = checked_tree(m);
  int64_t maxima = 0, at_zero = 0;
  for (const auto &n : t.nodes) {
    at_zero += n.value == 0.0;
    if (n.type == NodeType::Maximum) {
      ++maxima;
      EXPECT_EQ(n.value, 0.0);
    }
  }
  EXPECT_EQ(maxima, 1);
  EXPECT_EQ(at_zero, 1);
}

TEST(DegenerateFields, ConstantCellsAreFlatRegionsWithoutSubVertices) {
  // Zero left of the grid line x = x0 (a plateau of constant cubic cells), a cubic that vanishes
  // on that line to its right (positive next to it: the plateau is a minimum; cubic, so that the
  // cubic cells hold it exactly). Constant cells add no sub-vertices to the graph (their edges'
  // chains already bound them), and the cells along the plateau's edge need no fallback: where
  // the field rises across it (power 1) the edge is a level edge for them, where it leaves the
  // plateau flat (power 2: its gradient vanishes on the edge) a critical edge. The plateau is
  // one minimum, as in the PL tree of a fine refinement, and the two trees' diagrams agree.
  for (int power : {1, 2}) {
    SCOPED_TRACE("power " + std::to_string(power));
    const int n = 14;
    const double x0 = -1 + 2.0 * 5 / n;
    const Mesh m = build_mesh(grid_input(n, 3, [&](const Vec3 &p) {
      const double d = p[0] - x0;
      if (d <= 1e-12)
        return 0.0;
      return power == 1 ? d * (2 + 0.8 * p[1] - p[1] * p[1]) - d * d * (2.5 + 1.5 * p[1])
                        : d * d * (2 + 0.8 * p[1]) - 1.5 * d * d * d;
    }));
    const TreeResult raw = exact_contour_tree(m);
    auto stat = [&](const char *name) {
      for (const auto &[k, v] : raw.stats.entries())
        if (k == name)
          return static_cast<int64_t>(v);
      return int64_t{-1};
    };
    const int64_t constant = stat("fallback_constant_cell"), fallback = stat("fallback_cells");
    ASSERT_EQ(constant, 2 * 5 * n); // the cells left of x0
    // The line x0, seen from its right: level edges, or critical edges (a valley's border).
    EXPECT_EQ(fallback, constant);
    EXPECT_EQ(stat("level_edges"), power == 1 ? n : 0);
    EXPECT_EQ(stat("critical_curves"), power == 1 ? 0 : n);
    const int64_t refined_nodes = (fallback - constant) * 28; // (K + 1)(K + 2) / 2, K = 6
    EXPECT_LE(stat("graph_nodes"), m.topology.num_vertices() + stat("edge_critical_points") +
                                       stat("interior_critical_points") + refined_nodes);
    const TreeResult t = checked_tree(m);
    const TreeResult pl = contract_flat(pl_contour_tree(refine(m, 8), false, ""));
    auto plateau_minima = [](const TreeResult &tree) {
      int64_t count = 0;
      for (const auto &node : tree.nodes)
        count += node.type == NodeType::Minimum && node.value == 0.0;
      return count;
    };
    EXPECT_EQ(plateau_minima(t), 1);
    EXPECT_EQ(plateau_minima(pl), 1);
    const double range = m.field.max_value() - m.field.min_value();
    for (auto kind :
         {PersistencePair::Kind::Join, PersistencePair::Kind::Split, PersistencePair::Kind::Global})
      EXPECT_LT(bottleneck_distance(pair_points(t.pairs, kind), pair_points(pl.pairs, kind)),
                0.01 * range);
  }
}

TEST(DegenerateFields, SaddleOnAVertex) {
  // x^2 - y^2 (represented exactly by quadratic cells): the saddle at the origin, a mesh vertex.
  const Mesh m =
      build_mesh(grid_input(4, 2, [](const Vec3 &p) { return p[0] * p[0] - p[1] * p[1]; }));
  const TreeResult t = checked_tree(m);
  const TreeNode *s = node_at(t, 0, 0);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->type, NodeType::Saddle);
  EXPECT_EQ(s->location, NodeLocation::Vertex);
}

TEST(DegenerateFields, SaddleOnAnEdge) {
  // The grid shifted so that the origin is the midpoint of a horizontal edge.
  const double h = 2.0 / 4;
  const Mesh m = build_mesh(grid_input(
      4, 2, [](const Vec3 &p) { return p[0] * p[0] - p[1] * p[1]; }, h / 2, 0));
  const TreeResult t = checked_tree(m);
  const TreeNode *s = node_at(t, 0, 0);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->type, NodeType::Saddle);
  EXPECT_EQ(s->location, NodeLocation::Edge);
}

TEST(DegenerateFields, MonkeySaddleOnAVertex) {
  // x^3 - 3 x y^2: three lower and three upper sectors at the origin, a vertex.
  const Mesh m = build_mesh(
      grid_input(4, 3, [](const Vec3 &p) { return p[0] * p[0] * p[0] - 3 * p[0] * p[1] * p[1]; }));
  const TreeResult t = checked_tree(m);
  const TreeNode *s = node_at(t, 0, 0);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->type, NodeType::Saddle);
  EXPECT_GE(s->up + s->down, 4); // a double saddle: more than three arcs
}

TEST(DegenerateFields, TiesEverywhere) {
  // Values from {0, 1, 2} only: many equal values at vertices, edges and inside cells.
  for (int d = 1; d <= 3; ++d) {
    std::mt19937_64 rng(40 + d);
    const Mesh m =
        build_mesh(grid_input(5, d, [&](const Vec3 &) { return static_cast<double>(rng() % 3); }));
    checked_tree(m);
  }
}

TEST(DegenerateFields, NonFiniteValuesAreRefused) {
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    MeshInput in = grid_input(2, 2, [](const Vec3 &p) { return p[0]; });
    in.values[4] = bad;
    try {
      build_mesh(in);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const Error &e) {
      EXPECT_NE(std::string(e.what()).find("point 4 has value"), std::string::npos) << e.what();
    }
  }
}

TEST(DegenerateFields, HugeValuesAreRefusedBeforeTheyOverflow) {
  MeshInput in = grid_input(2, 3, [](const Vec3 &p) { return 1e200 * p[0]; });
  try {
    build_mesh(in);
    ADD_FAILURE() << "accepted values of 1e200";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("rescale the field"), std::string::npos) << e.what();
  }
}

TEST(DegenerateFields, TinyRangesAreRefusedBeforeTheyUnderflow) {
  for (double scale : {1e-160, 1e-250, 5e-324}) {
    MeshInput in = grid_input(2, 3, [&](const Vec3 &p) { return scale * p[0]; });
    try {
      build_mesh(in);
      ADD_FAILURE() << "accepted a value range of " << scale;
    } catch (const Error &e) {
      EXPECT_NE(std::string(e.what()).find("rescale the field"), std::string::npos) << e.what();
    }
  }
}

TEST(DegenerateFields, LargeAndTinyScalesGiveTheSameTree) {
  const Fn f = [](const Vec3 &p) {
    return std::sin(3 * p[0] + 0.2) * std::cos(2 * p[1]) + 0.1 * p[0];
  };
  const TreeResult ref = checked_tree(build_mesh(grid_input(5, 3, f)));
  for (double scale : {1e90, 1e-100, 1e-120, 1e-138}) {
    SCOPED_TRACE(scale);
    const TreeResult t =
        checked_tree(build_mesh(grid_input(5, 3, [&](const Vec3 &p) { return scale * f(p); })));
    ASSERT_EQ(t.nodes.size(), ref.nodes.size());
    EXPECT_EQ(t.arcs, ref.arcs);
    for (std::size_t i = 0; i < t.nodes.size(); ++i) {
      EXPECT_EQ(t.nodes[i].type, ref.nodes[i].type);
      EXPECT_NEAR(t.nodes[i].value / scale, ref.nodes[i].value, 1e-9);
    }
  }
}

} // namespace
} // namespace hoct

namespace hoct {
namespace {

// An edge whose derivative vanishes at a vertex within rounding: along v = 0,
// f = x^3 / 3 + 1e-14 x + 2 y has f' = x^2 + 1e-14, whose Bernstein coefficients are all
// positive but whose value at x = 0 is 1e-14 of its scale: root isolation reports a tangency at
// the vertex, and the edge is degenerate. The screen that skips monotone edges before building
// their polynomials must agree (it did not at first: it only asked for coefficients of one
// sign). The cell does not fall back: its corner at the vertex is classified by its sectors
// inside the cell (none there: the tree is the minimum (0, 0) and the maximum (0, 1)).
TEST(DegenerateFields, NearTangentEdgeDerivativeIsDegenerate) {
  std::mt19937_64 rng(3);
  const MeshInput in = testing::lagrange_mesh(
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, [](int64_t) { return 3; }, nullptr,
      [](const Vec3 &p) {
        const double x = p[0];
        return x * x * x / 3 + 1e-14 * x + 2 * p[1];
      },
      rng, false);
  const Mesh mesh = build_mesh(in);
  const EdgeNodes en = find_edge_nodes(mesh.topology, mesh.field);
  int root_at_vertex = 0;
  for (int64_t e = 0; e < mesh.topology.num_edges(); ++e)
    root_at_vertex += en.degeneracy[e] == kEdgeRootAtVertex;
  EXPECT_EQ(root_at_vertex, 1);
  const TreeResult t = exact_contour_tree(mesh);
  ASSERT_TRUE(t.stats.exact);
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
  EXPECT_EQ(t.stats.exact->critical_corners, 1);
  ASSERT_EQ(t.nodes.size(), 2u);
  EXPECT_EQ(t.nodes[0].value, 0);
  EXPECT_EQ(t.nodes[1].value, 2);
}

} // namespace
} // namespace hoct
