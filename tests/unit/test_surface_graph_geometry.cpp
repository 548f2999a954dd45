// The exact tree's geometric graph places its nodes and edge pieces on the surface only when an
// arc is drawn through them: the same points as the mesh's maps, none inside pieces of
// straight-sided cells, and arcs that can still be drawn once the mesh is gone.
#include "datasets/datasets.hpp"
#include "mesh/mesh.hpp"
#include "poly/lattice.hpp"
#include "tree/exact_contour_tree.hpp"
#include "tree/surface_graph_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace hoct {
namespace {

Mesh dataset_mesh(const std::string &name) {
  return build_mesh(generate_dataset(name, DatasetOptions{}));
}

TEST(SurfaceGraphGeometry, PlacesNodesAndPiecesThroughTheCellsMaps) {
  // The sphere's cells are all curved, the gauss disk's all straight-sided.
  for (const std::string name : {"sphere", "gauss"}) {
    const Mesh mesh = dataset_mesh(name);
    const Geometry &g = mesh.geometry;
    const int64_t c = g.num_cells() / 2, other = g.num_cells() / 3;
    const bool curved = name == "sphere";
    ASSERT_EQ(g.is_linear(c), !curved) << name;
    UninitializedVector<CellPoint> nodes(2);
    nodes[0] = {c, 0.2, 0.3};
    nodes[1] = {other, 0.6, 0.1};
    // A piece of local edge 0 (v = 0) of cell c, and one of local edge 2 (u = 0) of the other.
    UninitializedVector<EdgePiece> pieces(2);
    pieces[0] = {c, 0.1, 0.0, 0.7, 0.0};
    pieces[1] = {other, 0.0, 0.9, 0.0, 0.2};
    const SurfaceGraphGeometry sg(g, std::move(nodes), std::move(pieces));
    EXPECT_EQ(sg.node(0), g.position(c, 0.2, 0.3)) << name;
    EXPECT_EQ(sg.node(1), g.position(other, 0.6, 0.1)) << name;
    ASSERT_EQ(sg.edges(), 2);
    for (int e = 0; e < 2; ++e) {
      const EdgePiece p =
          e == 0 ? EdgePiece{c, 0.1, 0.0, 0.7, 0.0} : EdgePiece{other, 0.0, 0.9, 0.0, 0.2};
      std::vector<Vec3> forward, backward;
      sg.edge_points(e, true, forward);
      sg.edge_points(e, false, backward);
      // A straight-sided cell's piece is the segment between its ends: no points inside.
      const std::size_t expected = curved ? SurfaceGraphGeometry::kPiecePoints : 0;
      ASSERT_EQ(forward.size(), expected) << name << " " << e;
      ASSERT_EQ(backward.size(), expected) << name << " " << e;
      for (std::size_t j = 1; j <= expected; ++j) {
        const double s = static_cast<double>(j) / (SurfaceGraphGeometry::kPiecePoints + 1);
        EXPECT_EQ(forward[j - 1],
                  g.position(p.cell, p.u0 + (p.u1 - p.u0) * s, p.v0 + (p.v1 - p.v0) * s))
            << name << " " << e << " " << j;
        EXPECT_EQ(backward[expected - j], forward[j - 1]) << name << " " << e << " " << j;
      }
      // Appended, not replacing.
      sg.edge_points(e, true, forward);
      EXPECT_EQ(forward.size(), 2 * expected) << name;
    }
  }
}

TEST(SurfaceGraphGeometry, ArcsAreDrawnOnTheSurfaceAfterTheMeshIsGone) {
  // The sphere dataset: every node of its cubic cells on the unit sphere, so every point of a
  // curved cell is within the interpolation error of it.
  TreeResult tree;
  std::vector<std::vector<Vec3>> alive;
  {
    const Mesh mesh = dataset_mesh("sphere");
    ExactTreeOptions o;
    o.arc_geometry = true;
    tree = exact_contour_tree(mesh, o);
    TreeResult copy = tree;
    compute_arc_paths(copy, 2);
    alive = copy.arc_paths;
  }
  // The mesh is destroyed: the graph still holds the maps it places points with.
  compute_arc_paths(tree, 1);
  ASSERT_EQ(tree.arc_paths.size(), tree.arcs.size());
  ASSERT_EQ(alive.size(), tree.arcs.size());
  std::size_t points = 0;
  double longest = 0;
  for (std::size_t i = 0; i < tree.arc_paths.size(); ++i) {
    const auto &p = tree.arc_paths[i];
    ASSERT_EQ(p.size(), alive[i].size()) << i;
    EXPECT_EQ(std::memcmp(p.data(), alive[i].data(), p.size() * sizeof(Vec3)), 0) << i;
    ASSERT_GE(p.size(), 2u);
    EXPECT_EQ(p.front(), tree.nodes[tree.arcs[i][0]].position) << i;
    EXPECT_EQ(p.back(), tree.nodes[tree.arcs[i][1]].position) << i;
    for (const Vec3 &x : p) {
      const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      EXPECT_NEAR(r, 1.0, 1e-3) << "arc " << i;
    }
    // Step by step across the cells: no step longer than a cell (edges ~0.17 long here).
    for (std::size_t j = 0; j + 1 < p.size(); ++j) {
      double d2 = 0;
      for (int k = 0; k < 3; ++k)
        d2 += (p[j + 1][k] - p[j][k]) * (p[j + 1][k] - p[j][k]);
      longest = std::max(longest, std::sqrt(d2));
    }
    points += p.size();
  }
  EXPECT_LT(longest, 0.25);
  // The arcs pass through edge pieces' interior points, not only through graph nodes.
  EXPECT_GT(points, 2 * tree.arcs.size() + tree.arcs.size());
}

} // namespace
} // namespace hoct
