// The PL methods' Reeb graphs computed piece by piece (exact/pl_reeb_pieces, glued in groups by
// exact/reeb_group) against the one a single process computes (compute_tree with --linear and
// --refine 2: the whole PL mesh cut along its own cut graph, glued back): the plate (100 holes)
// with a plateau over part of it, an annulus, a Moebius strip and a torus, in 1, 2, 3, 4 and 7
// pieces of contiguous cells, reduced and augmented, every group through bytes as the ranks send
// it: the same nodes (value, cell, (u, v), position: bit for bit), arcs, loops and pairs.
#include "datasets/datasets.hpp"
#include "exact/piece_codec.hpp"
#include "exact/pl_reeb_pieces.hpp"
#include "mesh/mesh_partition.hpp"
#include "pipeline/compute_tree.hpp"

#include "test_meshes.hpp"
#include "test_same_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace hoct {
namespace {

// `k` 0: the linear method; else refine K.
TreeResult pl_reeb_by_pieces(const MeshInput &whole, int pieces, int k, bool augmented) {
  MeshScales scales;
  MeshBuildOptions wo;
  wo.whole_scales = [&](const MeshScales &own) { return scales = own; };
  const Mesh whole_mesh = build_mesh(whole, wo);
  const auto spans = point_piece_spans(whole, pieces);
  const auto sent = [](const ReebGroup &g) { return decode_reeb_group(encode_reeb_group(g)); };
  std::vector<ReebGroup> groups;
  double reference = 0;
  for (int r = 0; r < pieces; ++r) {
    const auto [begin, end] = piece_cell_range(static_cast<int64_t>(whole.num_cells()), pieces, r);
    const MeshPiece piece = extract_piece(whole, begin, end);
    const auto piece_spans = piece_point_spans(piece.global_point, spans);
    const PiecePlace place{r, piece.global_point, begin, triangles_before(whole, begin),
                           piece_spans};
    MeshBuildOptions bo;
    bo.throw_on_error = false;
    bo.whole_scales = [&](const MeshScales &) { return scales; };
    const Mesh mesh = build_mesh(piece.input, bo);
    reference = mesh.field.reference();
    const PlPieceMesh m =
        k == 0 ? linear_piece_mesh(piece.input, place) : refined_piece_mesh(mesh, place, k);
    groups.push_back(sent(pl_reeb_group(m, place, augmented, r % 2 + 1)));
  }
  for (int step = 1; step < pieces; step *= 2)
    for (int r = 0; r + step < pieces; r += 2 * step)
      groups[r] = sent(merge_reeb_groups(groups[r], groups[r + step], augmented));
  TreeResult graph = pl_reeb_graph_of_group(groups[0], augmented,
                                            k == 0 ? "linear" : "refine k=" + std::to_string(k),
                                            PlCounts{}, k == 0 ? 0.0 : reference);
  // Flat regions contracted as rank 0 finishes the tree (pipeline/finish_tree).
  return augmented ? graph : contract_flat(std::move(graph));
}

// `loops`: the domain's, where no plateau hides some (-1: not checked).
void check(const MeshInput &whole, const std::string &name, int64_t loops) {
  for (const int k : {0, 2})
    for (const bool augmented : {false, true}) {
      TreeRequest rq;
      rq.method = k == 0 ? TreeMethod::Linear : TreeMethod::Refine;
      rq.refine = k;
      rq.augmented = augmented;
      const TreeResult expected = compute_tree(build_mesh(whole), rq, &whole).tree;
      ASSERT_TRUE(expected.reeb_graph) << name;
      if (loops >= 0 && !augmented) {
        EXPECT_EQ(expected.loops, loops) << name;
      }
      for (const int pieces : {1, 2, 3, 4, 7}) {
        const std::string what = name + (k ? ", refine 2" : ", linear") +
                                 (augmented ? ", augmented, " : ", ") + std::to_string(pieces) +
                                 " pieces";
        const TreeResult got = pl_reeb_by_pieces(whole, pieces, k, augmented);
        testing::expect_same_graph(got, expected, what);
        EXPECT_EQ(got.method, expected.method) << what;
        EXPECT_EQ(got.loops, expected.loops) << what;
      }
    }
}

TEST(PlReebPieces, ThePlateAndItsPlateau) {
  DatasetOptions o;
  o.degree = 2;
  o.cells = 1500;
  MeshInput plate = generate_dataset("plate", o);
  check(plate, "plate", 100);
  // Values below the median raised to it: ties between copies and across pieces, ordered by
  // the whole's keys.
  std::vector<double> sorted(plate.values.begin(), plate.values.end());
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  for (double &v : plate.values)
    v = std::max(v, sorted[sorted.size() / 2]);
  check(plate, "plate with a plateau", -1);
}

TEST(PlReebPieces, AnnulusMoebiusStripAndTorus) {
  const auto wavy = [](const Vec3 &p) {
    return p[0] + 0.3 * std::sin(3 * p[1]) + 0.2 * std::cos(2 * p[2] + p[0]);
  };
  check(testing::surface_grid(40, 6, true, false, false, wavy), "annulus", 1);
  check(testing::surface_grid(41, 6, true, false, true, wavy), "Moebius strip", 1);
  check(testing::surface_grid(40, 12, true, true, false, wavy), "torus", 1);
}

} // namespace
} // namespace hoct
