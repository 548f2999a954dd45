// The exact tree's geometric graph places its nodes and edge pieces on the surface only when an
// arc is drawn through them: the same points as the mesh's maps, none inside pieces of
// straight-sided cells, and arcs that can still be drawn once the mesh is gone.
#include "datasets/datasets.hpp"
#include "exact/exact_contour_tree.hpp"
#include "exact/surface_graph_geometry.hpp"
#include "mesh/mesh.hpp"
#include "poly/lattice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace hoct {
namespace {

Mesh dataset_mesh(const std::string &name) {
  return build_mesh(generate_dataset(name, DatasetOptions{}));
}

TEST(SurfaceGraphGeometry, PlacesNodesAndCurvedPiecesThroughTheCellsMaps) {
  const Mesh mesh = dataset_mesh("sphere"); // every cell curved
  const Geometry &g = mesh.geometry;
  const int64_t c = g.num_cells() / 2, other = g.num_cells() / 3;
  ASSERT_FALSE(g.is_linear(c));
  UninitializedVector<CellPoint> nodes(2);
  nodes[0] = {c, 0.2, 0.3};
  nodes[1] = {other, 0.6, 0.1};
  // Edges 0 and 2 of 3 are curved pieces: of local edge 0 (v = 0) of cell c, and of local edge
  // 2 (u = 0) of the other cell; edge 1 is a piece of a straight-sided cell.
  const EdgePiece listed[2] = {{c, 0.1, 0.0, 0.7, 0.0}, {other, 0.0, 0.9, 0.0, 0.2}};
  UninitializedVector<int64_t> ids(2);
  ids[0] = 0;
  ids[1] = 2;
  UninitializedVector<EdgePiece> pieces(2);
  pieces[0] = listed[0];
  pieces[1] = listed[1];
  const SurfaceGraphGeometry sg(g, std::move(nodes), 3, std::move(ids), std::move(pieces));
  EXPECT_EQ(sg.node(0), g.position(c, 0.2, 0.3));
  EXPECT_EQ(sg.node(1), g.position(other, 0.6, 0.1));
  ASSERT_EQ(sg.edges(), 3);
  for (int e = 0; e < 3; ++e) {
    std::vector<Vec3> forward, backward;
    sg.edge_points(e, true, forward);
    sg.edge_points(e, false, backward);
    // A straight-sided cell's piece is the segment between its ends: no points inside.
    const std::size_t expected = e == 1 ? 0 : SurfaceGraphGeometry::kPiecePoints;
    ASSERT_EQ(forward.size(), expected) << e;
    ASSERT_EQ(backward.size(), expected) << e;
    if (e == 1)
      continue;
    const EdgePiece &p = listed[e / 2];
    for (std::size_t j = 1; j <= expected; ++j) {
      const double s = static_cast<double>(j) / (SurfaceGraphGeometry::kPiecePoints + 1);
      EXPECT_EQ(forward[j - 1],
                g.position(p.cell, p.u0 + (p.u1 - p.u0) * s, p.v0 + (p.v1 - p.v0) * s))
          << e << " " << j;
      EXPECT_EQ(backward[expected - j], forward[j - 1]) << e << " " << j;
    }
    // Appended, not replacing.
    sg.edge_points(e, true, forward);
    EXPECT_EQ(forward.size(), 2 * expected) << e;
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

TEST(SurfaceGraphGeometry, OnlyPiecesOfCurvedCellsGetPointsInside) {
  // A planar field on straight-sided cubic cells, then the same with the edge nodes in the left
  // third of the square moved a little (those cells curved, the others still straight). The
  // field is the same in every cell's reference triangle, so are the tree and the paths through
  // the graph; each piece of a curved cell's edge that an arc passes adds exactly its interior
  // points, every step stays short, and every point stays within the bend of the straight
  // mesh's path (a point of another piece would lie elsewhere).
  DatasetOptions o;
  o.cells = 2000;
  o.degree = 3;
  const MeshInput straight_input = generate_dataset("random", o);
  MeshInput bent_input = generate_dataset("random", o);
  std::vector<char> corner(bent_input.points.size(), 0);
  for (std::size_t c = 0; c < bent_input.num_cells(); ++c)
    for (int k = 0; k < 3; ++k)
      corner[bent_input.cell_nodes[bent_input.cell_offsets[c] +
                                   corner_index(bent_input.cell_degree[c], k)]] = 1;
  for (std::size_t i = 0; i < bent_input.points.size(); ++i) {
    Vec3 &p = bent_input.points[i];
    if (!corner[i] && p[0] < 1.0 / 3)
      p[1] += 0.002 * std::sin(40 * p[0]);
  }
  const Mesh straight = build_mesh(MeshInput(straight_input));
  const Mesh bent = build_mesh(std::move(bent_input));
  ASSERT_EQ(straight.geometry.curved_cells(), 0);
  ASSERT_GT(bent.geometry.curved_cells(), 100);
  ASSERT_LT(bent.geometry.curved_cells(), bent.geometry.num_cells() / 2);
  ExactTreeOptions eo;
  eo.arc_geometry = true;
  TreeResult a = exact_contour_tree(straight, eo), b = exact_contour_tree(bent, eo);
  ASSERT_EQ(a.arcs, b.arcs);
  compute_arc_paths(a, 1);
  compute_arc_paths(b, 2);
  std::size_t added = 0;
  double longest = 0;
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    ASSERT_GE(b.arc_paths[i].size(), a.arc_paths[i].size()) << i;
    const std::size_t extra = b.arc_paths[i].size() - a.arc_paths[i].size();
    EXPECT_EQ(extra % SurfaceGraphGeometry::kPiecePoints, 0u) << i;
    added += extra;
    const auto &p = b.arc_paths[i], &q = a.arc_paths[i];
    for (std::size_t j = 0; j + 1 < p.size(); ++j)
      longest = std::max(longest, std::hypot(p[j + 1][0] - p[j][0], p[j + 1][1] - p[j][1]));
    // Distance from each point to the straight path (its segments, or its one point).
    for (const Vec3 &x : p) {
      double nearest = std::hypot(x[0] - q[0][0], x[1] - q[0][1]);
      for (std::size_t j = 0; j + 1 < q.size(); ++j) {
        const double dx = q[j + 1][0] - q[j][0], dy = q[j + 1][1] - q[j][1];
        const double len2 = dx * dx + dy * dy;
        const double t =
            len2 > 0 ? std::clamp(((x[0] - q[j][0]) * dx + (x[1] - q[j][1]) * dy) / len2, 0.0, 1.0)
                     : 0.0;
        nearest = std::min(nearest, std::hypot(x[0] - q[j][0] - t * dx, x[1] - q[j][1] - t * dy));
      }
      // The bend moves edge nodes by at most 0.002, the curves between them a little more.
      EXPECT_LT(nearest, 0.004) << "arc " << i;
    }
  }
  EXPECT_GT(added, 0u);
  // Cells about 0.03 across here.
  EXPECT_LT(longest, 0.1);
}

} // namespace
} // namespace hoct
