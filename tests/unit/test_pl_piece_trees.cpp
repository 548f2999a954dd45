// The PL methods' trees computed piece by piece (exact/pl_piece_trees) against the whole mesh's
// PL tree (pl/pl_contour_tree of split_lagrange_cells, and of refine for K = 1, 2, 3): generated
// datasets (cubic triangles, a plateau whose ties are ordered by the whole's keys,
// quadrilaterals, a sphere, a field at +1e7) cut into 1, 2, 3, 4, 7 and 16 pieces of contiguous
// cells, their kept trees passed through bytes as the MPI ranks send them, must give the same
// nodes (type, value, cell, (u, v), position, location: bit for bit), arcs, pairs and PL counts,
// reduced and augmented. Also the PL mesh's own rules the pieces follow: a vertex is placed in
// the first cell that has it, and points no cell uses are no vertices.
#include "datasets/datasets.hpp"
#include "exact/piece_codec.hpp"
#include "exact/pl_piece_trees.hpp"
#include "mesh/mesh_partition.hpp"
#include "mesh/topology.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/pl_mesh.hpp"
#include "pl/refinement.hpp"

#include "test_pieces.hpp"
#include "test_same_tree.hpp"

#include <gtest/gtest.h>

namespace hoct {
namespace {

TreeResult linear_tree_by_pieces(const MeshInput &whole, int pieces, bool augmented) {
  const auto spans = point_piece_spans(whole, pieces);
  std::vector<PieceTrees> groups;
  int64_t triangles = 0, own_points = 0;
  for (int r = 0; r < pieces; ++r) {
    const auto [begin, end] = piece_cell_range(static_cast<int64_t>(whole.num_cells()), pieces, r);
    const MeshPiece piece = extract_piece(whole, begin, end);
    const auto piece_spans = piece_point_spans(piece.global_point, spans);
    const PiecePlace place{r, piece.global_point, begin, triangles_before(whole, begin),
                           piece_spans};
    PlPieceTrees p = pl_piece_trees(piece.input, place, augmented, r % 2 + 1);
    triangles += p.triangles;
    own_points += p.own_points;
    groups.push_back(decode_piece_trees(encode_piece_trees(p.trees)));
  }
  for (int step = 1; step < pieces; step *= 2)
    for (int r = 0; r + step < pieces; r += 2 * step)
      groups[r] = merge_piece_trees(groups[r], groups[r + step], augmented);
  return pl_tree_of_pieces(groups[0], augmented, "linear",
                           whole_pl_counts(triangles, own_points, 0, 0, 0), 0.0);
}

// The same by the refine method (each piece's mesh built with the whole's scales).
TreeResult refined_tree_by_pieces(const MeshInput &whole, int pieces, int k,
                                  const MeshScales &scales, int64_t euler_characteristic,
                                  bool augmented) {
  double reference = 0;
  int64_t counts[3] = {0, 0, 0};
  std::vector<PieceTrees> groups = testing::pieces_of(
      whole, pieces, scales, augmented, reference,
      [&](const Mesh &m, const PiecePlace &p, const ExactTreeOptions &eo, TreeTimings &) {
        PlPieceTrees t = refined_piece_trees(m, p, k, eo.augmented, p.piece % 2 + 1);
        counts[0] += t.triangles;
        counts[1] += t.own_points;
        counts[2] += t.cell_points;
        return t.trees;
      });
  for (int step = 1; step < pieces; step *= 2)
    for (int r = 0; r + step < pieces; r += 2 * step)
      groups[r] = merge_piece_trees(groups[r], groups[r + step], augmented);
  return pl_tree_of_pieces(
      groups[0], augmented, "refine k=" + std::to_string(k),
      whole_pl_counts(counts[0], counts[1], counts[2], k, euler_characteristic), reference);
}

// Nodes, arcs, pairs, the method and the PL mesh's counts.
void expect_same_pl_tree(const TreeResult &a, const TreeResult &b, const std::string &what) {
  EXPECT_EQ(a.method, b.method) << what;
  testing::expect_same_graph(a, b, what);
  ASSERT_TRUE(a.stats.pl && b.stats.pl) << what;
  EXPECT_EQ(a.stats.pl->vertices, b.stats.pl->vertices) << what;
  EXPECT_EQ(a.stats.pl->triangles, b.stats.pl->triangles) << what;
}

void check_all_piece_counts(const MeshInput &whole, const std::string &name) {
  const PlMesh pl = split_lagrange_cells(whole);
  for (bool augmented : {false, true}) {
    const TreeResult expected = pl_contour_tree(pl, augmented, "linear");
    ASSERT_GT(expected.nodes.size(), 1u) << name;
    for (int pieces : {1, 2, 3, 4, 7, 16})
      expect_same_pl_tree(linear_tree_by_pieces(whole, pieces, augmented), expected,
                          name + (augmented ? " augmented, " : ", ") + std::to_string(pieces) +
                              " pieces");
  }
}

void check_refined(const MeshInput &whole, const std::string &name) {
  MeshScales scales;
  MeshBuildOptions bo;
  bo.whole_scales = [&](const MeshScales &own) { return scales = own; };
  const Mesh mesh = build_mesh(whole, bo);
  for (int k : {1, 2, 3})
    for (bool augmented : {false, true}) {
      const std::string method = "refine k=" + std::to_string(k);
      TreeResult expected = pl_contour_tree(refine(mesh, k), augmented, method);
      for (TreeNode &n : expected.nodes) { // the input's cells, as compute_tree reports them
        const CellPlace p = mesh.origins.to_input(n.cell, n.uv);
        n.cell = p.cell;
        n.uv = p.uv;
      }
      ASSERT_GT(expected.nodes.size(), 1u) << name;
      for (int pieces : {1, 2, 3, 4, 7, 16})
        expect_same_pl_tree(refined_tree_by_pieces(whole, pieces, k, scales,
                                                   mesh.topology.euler_characteristic(), augmented),
                            expected,
                            name + ", " + method + (augmented ? " augmented, " : ", ") +
                                std::to_string(pieces) + " pieces");
    }
}

// The datasets both methods are checked on (`scale`: the cells of the triangle meshes).
std::vector<std::pair<std::string, MeshInput>> datasets(int scale) {
  std::vector<std::pair<std::string, MeshInput>> out;
  DatasetOptions o;
  o.cells = scale;
  out.emplace_back("cubic random", generate_dataset("random", o));
  out.emplace_back("sphere", generate_dataset("sphere", o));
  o.plateau = 30; // ties: ordered by the whole's keys in every piece
  out.emplace_back("random with a plateau", generate_dataset("random", o));
  DatasetOptions q;
  q.cells = scale / 3;
  q.quadrilaterals = true;
  out.emplace_back("random quadrilaterals", generate_dataset("random", q));
  DatasetOptions d;
  d.cells = scale / 2;
  d.degree = 5;
  d.offset = 1e7;
  out.emplace_back("random quintic at 1e7", generate_dataset("random", d));
  return out;
}

TEST(PlPieceTrees, TheWholeMeshsRefinedTreeForAnyNumberOfPieces) {
  for (const auto &[name, whole] : datasets(1000))
    check_refined(whole, name);
}

TEST(PlPieceTrees, TheWholeMeshsLinearTreeForAnyNumberOfPieces) {
  for (const auto &[name, whole] : datasets(3000))
    check_all_piece_counts(whole, name);
  DatasetOptions o;
  o.cells = 3000;
  check_all_piece_counts(generate_dataset("gauss", o), "gauss");
}

// Two linear triangles sharing the edge 1-2, and a point no cell uses.
MeshInput two_triangles_and_a_stray_point() {
  MeshInput m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {5, 5, 0}};
  m.values = {0, 1, 2, 3, 9};
  const int64_t a[3] = {0, 1, 2}, b[3] = {1, 3, 2};
  m.add_cell(1, a);
  m.add_cell(1, b);
  return m;
}

TEST(PlPieceTrees, VerticesSitInTheirFirstCellAndUnusedPointsAreNone) {
  const MeshInput m = two_triangles_and_a_stray_point();
  const PlMesh pl = split_lagrange_cells(m);
  ASSERT_EQ(pl.points.size(), 4u); // the stray point left out
  EXPECT_EQ(pl.source_cell[1], 0); // points 1 and 2 are in both cells: the first wins
  EXPECT_EQ(pl.source_cell[2], 0);
  EXPECT_EQ(pl.source_cell[3], 1);
  EXPECT_EQ(pl.source_uv[2], (std::array<double, 2>{0, 1}));
  const PlMesh all = split_lagrange_cells(m, /*keep_unused_points=*/true);
  ASSERT_EQ(all.points.size(), 5u);
  EXPECT_EQ(all.source_cell[4], -1);
  // The linear field rises from point 0 to point 3: one minimum, one maximum, one arc (the
  // stray point would be a component of its own).
  const TreeResult t = pl_contour_tree(pl, false, "linear");
  ASSERT_EQ(t.nodes.size(), 2u);
  EXPECT_EQ(t.nodes[0].value, 0);
  EXPECT_EQ(t.nodes[1].value, 3);
  EXPECT_EQ(t.arcs.size(), 1u);
  EXPECT_EQ(t.stats.pl->vertices, 4);
  // By pieces, one triangle each: the same.
  expect_same_pl_tree(linear_tree_by_pieces(m, 2, false), t, "two pieces");
}

} // namespace
} // namespace hoct
