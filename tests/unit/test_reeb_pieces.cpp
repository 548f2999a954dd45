// The exact Reeb graph computed piece by piece (exact/reeb_pieces) against the one a single
// process computes from its own cut of the whole mesh: the plate (100 holes) of degrees 2 and 3,
// with a plateau (fallback cells across the pieces), with its cells shuffled (pieces that hold
// several fans around the points they share), an annulus, a Moebius strip and a torus, cut into
// 1, 2, 3, 4, 7 and 16 pieces of contiguous cells: the same nodes (type, value, place: bit for
// bit), arcs, pairs, loops and counts. Also: a point where a piece holds two fans is cut apart
// (mesh/cut_surface's split vertices).
#include "datasets/datasets.hpp"
#include "exact/exact_contour_tree.hpp"
#include "exact/piece_codec.hpp"
#include "exact/reeb_group.hpp"
#include "exact/reeb_pieces.hpp"
#include "mesh/cut_surface.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_partition.hpp"
#include "test_meshes.hpp"
#include "test_pieces.hpp"
#include "test_same_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace hoct {
namespace {

using testing::surface_grid;

// The Reeb graph as one process computes it (pipeline/compute_tree): the whole mesh cut open
// along its cut graph, the disks' tree glued back.
TreeResult whole_reeb_graph(const MeshInput &whole, MeshScales &scales, bool augmented) {
  MeshBuildOptions bo;
  bo.whole_scales = [&](const MeshScales &own) { return scales = own; };
  const Mesh mesh = build_mesh(whole, bo);
  const std::vector<int64_t> cut_edges = cut_graph_edges(mesh.topology);
  const CutSurface cut = cut_open(mesh, cut_edges);
  ExactTreeOptions eo;
  eo.augmented = augmented;
  eo.threads = 1;
  eo.cut = &cut;
  return exact_contour_tree(cut.mesh, eo);
}

// The same from `pieces` pieces, each through bytes as the ranks send them, glued in groups:
// pairwise in a binary tree as the ranks merge them (distributed/distributed_tree), or by a left
// fold (`fold`: the first piece's group takes in the others one by one), each group through
// bytes before a merge.
TreeResult reeb_graph_by_pieces(const MeshInput &whole, int pieces, const MeshScales &scales,
                                bool augmented, bool fold = false) {
  double reference = 0;
  const std::vector<PieceTrees> all =
      testing::pieces_of(whole, pieces, scales, augmented, reference,
                         [](const Mesh &m, const PiecePlace &p, const ExactTreeOptions &eo,
                            TreeTimings &time) { return reeb_piece(m, p, eo, time); });
  const auto sent = [](const ReebGroup &g) { return decode_reeb_group(encode_reeb_group(g)); };
  std::vector<ReebGroup> groups;
  for (const PieceTrees &p : all)
    groups.push_back(sent(reeb_group(p, augmented)));
  if (fold) {
    for (std::size_t r = 1; r < groups.size(); ++r)
      groups[0] = sent(merge_reeb_groups(groups[0], groups[r], augmented));
  } else {
    for (std::size_t step = 1; step < groups.size(); step *= 2)
      for (std::size_t r = 0; r + step < groups.size(); r += 2 * step)
        groups[r] = sent(merge_reeb_groups(groups[r], groups[r + step], augmented));
  }
  return reeb_graph_of_group(groups[0], augmented, reference);
}

void expect_same_graph(const TreeResult &a, const TreeResult &b, const std::string &what) {
  testing::expect_same_tree(a, b, what);
  EXPECT_EQ(a.loops, b.loops) << what;
  EXPECT_EQ(a.stats.seam_paths_nonmonotone, b.stats.seam_paths_nonmonotone) << what;
}

// Returns the whole's loops (for the caller to check against the domain's). `flagged`: the
// piece counts whose gluing met seam pieces that do not rise (ties with fallback nodes on a
// plateau, between pieces): those the distributed tree hands to rank 0's whole mesh, so they
// are not compared; without it, every count must give the whole's graph.
int64_t check_all_piece_counts(const MeshInput &whole, const std::string &name,
                               int *flagged = nullptr) {
  MeshScales scales;
  int64_t loops = -1;
  for (bool augmented : {false, true}) {
    const TreeResult expected = whole_reeb_graph(whole, scales, augmented);
    EXPECT_EQ(expected.stats.seam_paths_nonmonotone, 0) << name;
    if (!augmented)
      loops = expected.loops;
    for (int pieces : {1, 2, 3, 4, 7, 16}) {
      const std::string what =
          name + (augmented ? " augmented" : "") + ", " + std::to_string(pieces) + " pieces";
      const TreeResult got = reeb_graph_by_pieces(whole, pieces, scales, augmented);
      if (flagged && got.stats.seam_paths_nonmonotone.value_or(0) > 0) {
        ++*flagged;
        continue;
      }
      expect_same_graph(got, expected, what);
      if (pieces >= 3) // another order of merges, the same graph
        expect_same_graph(reeb_graph_by_pieces(whole, pieces, scales, augmented, true), expected,
                          what + ", folded");
    }
  }
  return loops;
}

MeshInput plate(int degree, int cells) {
  DatasetOptions o;
  o.degree = degree;
  o.cells = cells;
  return generate_dataset("plate", o);
}

TEST(ReebPieces, ThePlateForAnyNumberOfPieces) {
  EXPECT_EQ(check_all_piece_counts(plate(3, 2000), "cubic plate"), 100);
  EXPECT_EQ(check_all_piece_counts(plate(2, 1500), "quadratic plate"), 100);
}

TEST(ReebPieces, APlateauOnThePlate) {
  // Every node value below the median raised to it: constant cells and level edges, fallback
  // cells on the seams and between the pieces, ties between copies and across pieces.
  MeshInput in = plate(2, 1500);
  std::vector<double> sorted(in.values.begin(), in.values.end());
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double floor = sorted[sorted.size() / 2];
  for (double &v : in.values)
    v = std::max(v, floor);
  int flagged = 0;
  EXPECT_EQ(check_all_piece_counts(in, "plate with a plateau", &flagged), 100);
  // 4 of the 12 (4 and 16 pieces, reduced and augmented) tie with a lattice node on a seam
  // between pieces; the others match the whole bit for bit.
  EXPECT_LE(flagged, 4);
}

TEST(ReebPieces, ShuffledCellsGivePiecesWithSeveralFansAtASharedPoint) {
  const MeshInput in = plate(2, 1500);
  std::vector<int64_t> order(in.num_cells());
  std::iota(order.begin(), order.end(), int64_t{0});
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  MeshInput shuffled;
  shuffled.points.assign(in.points.begin(), in.points.end());
  shuffled.values.assign(in.values.begin(), in.values.end());
  for (const int64_t c : order)
    shuffled.add_cell(in.cell_degree[c], &in.cell_nodes[in.cell_offsets[c]]);
  EXPECT_EQ(check_all_piece_counts(shuffled, "shuffled plate"), 100);
}

TEST(ReebPieces, AnnulusMoebiusStripAndTorus) {
  const auto wavy = [](const Vec3 &p) {
    return p[0] + 0.3 * std::sin(3 * p[1]) + 0.2 * std::cos(2 * p[2] + p[0]);
  };
  EXPECT_EQ(check_all_piece_counts(surface_grid(40, 6, true, false, false, wavy), "annulus"), 1);
  EXPECT_EQ(check_all_piece_counts(surface_grid(41, 6, true, false, true, wavy), "Moebius strip"),
            1);
  EXPECT_EQ(check_all_piece_counts(surface_grid(40, 12, true, true, false, wavy), "torus"), 1);
}

TEST(ReebPieces, BytesThatAreNotAReebGroupAreRefused) {
  // The first of 2 pieces of the plate: a group with open chains and their routes.
  const MeshInput whole = plate(2, 1500);
  MeshScales scales;
  MeshBuildOptions wo;
  wo.whole_scales = [&](const MeshScales &own) { return scales = own; };
  (void)build_mesh(whole, wo);
  double reference = 0;
  const std::vector<PieceTrees> pieces =
      testing::pieces_of(whole, 2, scales, false, reference,
                         [](const Mesh &m, const PiecePlace &p, const ExactTreeOptions &eo,
                            TreeTimings &time) { return reeb_piece(m, p, eo, time); });
  const ReebGroup group = reeb_group(pieces[0], false);
  ASSERT_FALSE(group.chains.empty());
  const auto bytes = encode_reeb_group(group);
  EXPECT_NO_THROW(decode_reeb_group(bytes));
  EXPECT_THROW(decode_reeb_group(std::span(bytes).first(bytes.size() - 1)), std::runtime_error);
  auto bad = bytes;
  bad[0] = std::byte{0};
  EXPECT_THROW(decode_reeb_group(bad), std::runtime_error);
  auto extra = bytes;
  extra.push_back(std::byte{0});
  EXPECT_THROW(decode_reeb_group(extra), std::runtime_error);
  EXPECT_THROW(decode_piece_trees(bytes), std::runtime_error); // not kept trees
  // Indices past their arrays: a chain's node, a route's arc, an arc's end.
  for (int k = 0; k < 3; ++k) {
    ReebGroup broken = group;
    auto &c = *std::find_if(broken.chains.begin(), broken.chains.end(),
                            [](const ReebChain &x) { return !x.route_arcs.empty(); });
    if (k == 0)
      c.nodes[0] = static_cast<int64_t>(broken.nodes.size());
    else if (k == 1)
      c.route_arcs[0] = static_cast<int64_t>(broken.arcs.size());
    else
      broken.arcs[0][1] = -1;
    EXPECT_THROW(decode_reeb_group(encode_reeb_group(broken)), std::runtime_error) << k;
  }
}

TEST(ReebPieces, APointWithTwoFansInAPieceIsCutApart) {
  // Two triangles touching at point 0 only (a bow tie): split there, two copies, two disks.
  MeshInput in;
  in.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  in.values = {0, 1, 2, 3, 4};
  const int64_t a[3] = {0, 1, 2}, b[3] = {0, 3, 4};
  in.add_cell(1, a);
  in.add_cell(1, b);
  const std::vector<uint8_t> open{1, 0, 0, 0, 0};
  MeshBuildOptions bo;
  bo.throw_on_error = false;
  bo.open_points = open;
  const Mesh mesh = build_mesh(in, bo);
  const std::vector<int64_t> split{0};
  const CornerCut corners = cut_corners(mesh.topology, {}, split);
  EXPECT_EQ(corners.first[1] - corners.first[0], 2);
  ASSERT_EQ(corners.group_offset.size(), 2u);
  const CutSurface cut = cut_open(mesh, {}, split);
  EXPECT_EQ(cut.mesh.topology.num_vertices(), 6);
  EXPECT_EQ(cut.mesh.topology.boundary_loops(), 2);
  // The lower cell's corner keeps the first copy.
  EXPECT_EQ(cut.mesh.topology.cell_vertices(0)[0], 0);
  EXPECT_EQ(cut.mesh.topology.cell_vertices(1)[0], 1);
}

} // namespace
} // namespace hoct
