// The exact tree computed piece by piece (exact/piece_trees) against the whole mesh's tree:
// every generated dataset (and plateaus, fallback cells, quadrilaterals), cut into 1, 2, 3, 4,
// 7 and 16 pieces of contiguous cells, must give the same nodes (type, value, place: bit for bit),
// arcs, pairs and counts.
#include "datasets/datasets.hpp"
#include "exact/exact_contour_tree.hpp"
#include "exact/piece_codec.hpp"
#include "exact/piece_trees.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_partition.hpp"
#include "mesh/topology.hpp"
#include "tree/sweep_contour_tree.hpp"

#include "test_pieces.hpp"
#include "test_same_tree.hpp"

#include <gtest/gtest.h>

#include <random>

namespace hoct {
namespace {

// The tree of `whole` from `pieces` pieces merged in a binary tree of groups, as the MPI ranks
// merge them (pipeline/distributed_tree).
TreeResult tree_by_pieces(const MeshInput &whole, int pieces, const MeshScales &scales,
                          bool augmented) {
  double reference = 0;
  std::vector<PieceTrees> groups =
      testing::pieces_of(whole, pieces, scales, augmented, reference,
                         [](const Mesh &m, const PiecePlace &p, const ExactTreeOptions &eo,
                            TreeTimings &time) { return piece_trees(m, p, eo, time); });
  for (int step = 1; step < pieces; step *= 2)
    for (int r = 0; r + step < pieces; r += 2 * step)
      groups[r] = merge_piece_trees(groups[r], groups[r + step], augmented);
  return tree_of_pieces(groups[0], augmented, reference);
}

using testing::expect_same_tree;

void check_all_piece_counts(const MeshInput &whole, const std::string &name) {
  MeshScales scales;
  MeshBuildOptions bo;
  bo.whole_scales = [&](const MeshScales &own) { return scales = own; };
  const Mesh mesh = build_mesh(whole, bo);
  for (bool augmented : {false, true}) {
    ExactTreeOptions eo;
    eo.augmented = augmented;
    eo.threads = 1;
    TreeResult expected = exact_contour_tree(mesh, eo);
    for (TreeNode &n : expected.nodes) // the input's cells, as the pieces report them
      if (!mesh.origins.identity()) {
        const CellPlace p = mesh.origins.to_input(n.cell, n.uv);
        n.cell = p.cell;
        n.uv = p.uv;
      }
    ASSERT_GT(expected.nodes.size(), 1u) << name;
    for (int pieces :
         {1, 2, 3, 4, 7, 16}) { // 16: small pieces, numbered by a sort (mesh_partition)
      const std::string what =
          name + (augmented ? " augmented" : "") + ", " + std::to_string(pieces) + " pieces";
      const TreeResult got = tree_by_pieces(whole, pieces, scales, augmented);
      expect_same_tree(got, expected, what);
    }
  }
}

TEST(PieceTrees, EveryDatasetGivesTheWholeMeshsTreeForAnyNumberOfPieces) {
  int checked = 0;
  for (const std::string &name : dataset_names()) {
    DatasetOptions o;
    o.cells = name == "two-triangle" ? 0
              : name == "heater"     ? 1500
              : name == "conductor"  ? 1200
                                     : 3000;
    MeshInput whole = generate_dataset(name, o);
    // Genus 0 only: a Reeb graph needs the surface cut open (not yet distributed).
    const Mesh m = build_mesh(whole, {.throw_on_error = false});
    const Topology &t = m.topology;
    if (t.components() != 1 || !((t.euler_characteristic() == 1 && t.boundary_loops() == 1) ||
                                 (t.euler_characteristic() == 2 && t.boundary_loops() == 0)))
      continue;
    check_all_piece_counts(whole, name);
    ++checked;
  }
  EXPECT_GE(checked, 5); // two-triangle, gauss, heater, conductor, sphere, random
}

TEST(PieceTrees, PlateausFallbackCellsAndQuadrilaterals) {
  DatasetOptions o;
  o.cells = 2000;
  o.plateau = 30; // constant cells and degenerate edges: fallback cells across the pieces
  // Ties on the plateau, fallback lattice nodes on edges between pieces (SharedChain).
  check_all_piece_counts(generate_dataset("random", o), "random with a plateau");
  o.degree = 2;
  o.seed = 7;
  check_all_piece_counts(generate_dataset("random", o), "quadratic random with a plateau");
  DatasetOptions q;
  q.cells = 800;
  q.quadrilaterals = true;
  check_all_piece_counts(generate_dataset("random", q), "random quadrilaterals");
  DatasetOptions d;
  d.cells = 1500;
  d.degree = 5;
  d.offset = 1e7; // a far reference: every piece must use the whole's
  check_all_piece_counts(generate_dataset("random", d), "random quintic at 1e7");
}

TEST(PieceTrees, BytesThatAreNotPieceTreesAreRefused) {
  DatasetOptions o;
  o.cells = 200;
  const MeshInput whole = generate_dataset("random", o);
  const MeshPiece piece = extract_piece(whole, 0, 100);
  const auto spans = point_piece_spans(whole, 2);
  const Mesh mesh = build_mesh(piece.input, {.throw_on_error = false});
  TreeTimings time;
  const auto bytes = encode_piece_trees(
      piece_trees(mesh, {0, piece.global_point, 0, 0, piece_point_spans(piece.global_point, spans)},
                  ExactTreeOptions{}, time));
  EXPECT_NO_THROW(decode_piece_trees(bytes));
  EXPECT_THROW(decode_piece_trees(std::span(bytes).first(bytes.size() - 1)), std::runtime_error);
  auto bad = bytes;
  bad[0] = std::byte{0};
  EXPECT_THROW(decode_piece_trees(bad), std::runtime_error);
  auto extra = bytes;
  extra.push_back(std::byte{0});
  EXPECT_THROW(decode_piece_trees(extra), std::runtime_error);
}

} // namespace
} // namespace hoct
