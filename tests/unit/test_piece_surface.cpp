// The whole surface's shape merged from its pieces' summaries (mesh/piece_surface), pairwise in a
// binary tree (as the ranks merge them) and one piece after another, against the whole mesh's
// own topology: annulus, torus, Moebius strip, a plate with holes, a sphere and a
// disk, cut into 1 to 16 pieces of contiguous cells, in the file's order and with the cells
// shuffled (ragged pieces, whose fans at shared points come in several wedges); and surfaces
// that are not manifold only where pieces meet.
#include "datasets/datasets.hpp"
#include "mesh/mesh_partition.hpp"
#include "mesh/piece_surface.hpp"
#include "mesh/topology.hpp"

#include <gtest/gtest.h>

#include "test_meshes.hpp"

#include <cmath>
#include <numeric>
#include <random>

namespace hoct {
namespace {

struct Glued {
  SurfaceShape shape;        // merged in a binary tree, as the ranks merge them
  SurfaceShape left_fold;    // merged one piece after another
  ProblemLog piece_problems; // what the pieces' own topologies found
};

Glued glue(const MeshInput &whole, int pieces) {
  const auto spans = point_piece_spans(whole, pieces);
  std::vector<PieceSurface> summaries;
  Glued out;
  for (int r = 0; r < pieces; ++r) {
    const auto [begin, end] = piece_cell_range(static_cast<int64_t>(whole.num_cells()), pieces, r);
    if (begin == end)
      continue;
    const MeshPiece piece = extract_piece(whole, begin, end);
    const auto piece_spans = piece_point_spans(piece.global_point, spans);
    std::vector<uint8_t> open(piece.global_point.size());
    for (std::size_t i = 0; i < open.size(); ++i)
      open[i] = piece_spans[i][0] != piece_spans[i][1];
    const Topology t = Topology::build(piece.input, out.piece_problems, 1, open);
    const PieceSurface s = summarize_piece(t, piece.global_point, piece_spans, r, 2);
    // Through bytes, as the ranks send them.
    summaries.push_back(decode_piece_surface(encode_piece_surface(s)));
  }
  PieceSurface fold = summaries.front();
  for (std::size_t k = 1; k < summaries.size(); ++k) // through bytes too
    fold = decode_piece_surface(encode_piece_surface(merge_piece_surfaces(fold, summaries[k])));
  EXPECT_TRUE(fold.open.empty() && fold.band.empty() && fold.loop_ends.empty());
  out.left_fold = surface_shape(fold);
  std::reverse(summaries.begin(), summaries.end()); // any order
  out.shape = glue_pieces(summaries);
  return out;
}

void expect_same_shape(const SurfaceShape &a, const SurfaceShape &b, const std::string &what) {
  EXPECT_EQ(a.components, b.components) << what;
  EXPECT_EQ(a.euler_characteristic, b.euler_characteristic) << what;
  EXPECT_EQ(a.boundary_loops, b.boundary_loops) << what;
  EXPECT_EQ(a.orientable, b.orientable) << what;
  EXPECT_EQ(a.seam_problem.empty(), b.seam_problem.empty()) << what;
}

// The same cells in a shuffled order.
MeshInput shuffled(const MeshInput &in, uint64_t seed) {
  std::vector<std::size_t> order(in.num_cells());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937_64 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  MeshInput out;
  out.points = in.points;
  out.values = in.values;
  for (const std::size_t c : order)
    out.add_cell(in.cell_degree[c], &in.cell_nodes[in.cell_offsets[c]]);
  return out;
}

MeshInput grid(int nu, int nv, bool wrap_u, bool wrap_v, bool twist) {
  return testing::surface_grid(nu, nv, wrap_u, wrap_v, twist, [](const Vec3 &p) { return p[0]; });
}

// The square grid without the squares in [lo, hi)^2: an annulus.
MeshInput holed_grid(int n, int lo, int hi) {
  MeshInput g = grid(n, n, false, false, false), out;
  out.points = g.points;
  out.values = g.values;
  for (std::size_t c = 0; c < g.num_cells(); ++c) {
    const int square = static_cast<int>(c / 2), i = square % n, j = square / n;
    if (i >= lo && i < hi && j >= lo && j < hi)
      continue;
    out.add_cell(1, &g.cell_nodes[g.cell_offsets[c]]);
  }
  return out;
}

TEST(PieceSurface, GluedShapeIsTheWholeMeshs) {
  DatasetOptions plate;
  plate.cells = 3000;
  plate.degree = 2;
  DatasetOptions small;
  small.cells = 2000;
  const std::vector<std::pair<std::string, MeshInput>> meshes = {
      {"disk", grid(10, 7, false, false, false)},    {"annulus", holed_grid(9, 3, 6)},
      {"torus", grid(12, 8, true, true, false)},     {"moebius", grid(16, 3, true, false, true)},
      {"cylinder", grid(16, 3, true, false, false)}, {"plate", generate_dataset("plate", plate)},
      {"sphere", generate_dataset("sphere", small)}, {"random", generate_dataset("random", small)}};
  for (const auto &[name, in] : meshes)
    for (const bool shuffle : {false, true}) {
      const MeshInput whole = shuffle ? shuffled(in, 7) : in;
      ProblemLog problems;
      const Topology t = Topology::build(whole, problems);
      ASSERT_FALSE(problems.has_errors()) << name;
      for (const int pieces : {1, 2, 3, 4, 7, 16}) {
        const std::string what =
            name + (shuffle ? " shuffled" : "") + ", " + std::to_string(pieces) + " pieces";
        const Glued g = glue(whole, pieces);
        EXPECT_FALSE(g.piece_problems.has_errors()) << what << "\n" << g.piece_problems.summary();
        EXPECT_EQ(g.shape.seam_problem, "") << what;
        EXPECT_EQ(g.shape.components, t.components()) << what;
        EXPECT_EQ(g.shape.euler_characteristic, t.euler_characteristic()) << what;
        EXPECT_EQ(g.shape.boundary_loops, t.boundary_loops()) << what;
        EXPECT_EQ(g.shape.orientable, t.orientable()) << what;
        expect_same_shape(g.left_fold, g.shape, what + ", one piece after another");
      }
    }
}

// Two separate disks and a disk made of two parts touching at one vertex only: the glue counts
// the components, and names the vertex where the pieces' fans do not close into one.
TEST(PieceSurface, PartsTouchingWhereThePiecesMeet) {
  MeshInput bowtie;
  bowtie.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {2, 2, 0}};
  bowtie.values.assign(bowtie.points.size(), 0);
  const int64_t a[3] = {0, 1, 2}, b[3] = {0, 3, 4}, c[3] = {1, 5, 2};
  bowtie.add_cell(1, a);
  bowtie.add_cell(1, c);
  bowtie.add_cell(1, b); // the second part, at point 0 only
  ProblemLog whole_problems;
  Topology::build(bowtie, whole_problems);
  ASSERT_GT(whole_problems.count(Problem::NonManifoldVertex), 0);
  for (const int pieces : {2, 3}) {
    const Glued g = glue(bowtie, pieces);
    EXPECT_FALSE(g.piece_problems.has_errors()) << pieces; // each piece alone is fine
    EXPECT_NE(g.shape.seam_problem.find("at point 0 form 2 fans"), std::string::npos)
        << pieces << ": " << g.shape.seam_problem;
    EXPECT_NE(g.left_fold.seam_problem.find("at point 0 form 2 fans"), std::string::npos)
        << pieces << ": " << g.left_fold.seam_problem;
  }
  // Three triangles on one edge, one per piece.
  MeshInput book;
  book.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  book.values.assign(book.points.size(), 0);
  const int64_t p1[3] = {0, 1, 2}, p2[3] = {1, 0, 3}, p3[3] = {0, 1, 4};
  book.add_cell(1, p1);
  book.add_cell(1, p2);
  book.add_cell(1, p3);
  const Glued g = glue(book, 3);
  EXPECT_FALSE(g.piece_problems.has_errors());
  EXPECT_NE(g.shape.seam_problem.find("shared by 3 cells"), std::string::npos)
      << g.shape.seam_problem;
  EXPECT_NE(g.left_fold.seam_problem.find("shared by 3 cells"), std::string::npos)
      << g.left_fold.seam_problem;
  // Two disks apart: two components, two loops.
  MeshInput two = grid(4, 4, false, false, false);
  const MeshInput other = two;
  const int64_t base = static_cast<int64_t>(two.points.size());
  for (const Vec3 &p : other.points)
    two.points.push_back({p[0] + 10, p[1], p[2]});
  two.values.insert(two.values.end(), other.values.begin(), other.values.end());
  for (std::size_t cell = 0; cell < other.num_cells(); ++cell) {
    int64_t n[3];
    for (int k = 0; k < 3; ++k)
      n[k] = other.cell_nodes[other.cell_offsets[cell] + k] + base;
    two.add_cell(1, n);
  }
  for (const int pieces : {1, 2, 3, 5}) {
    const Glued h = glue(shuffled(two, 3), pieces);
    EXPECT_EQ(h.shape.components, 2) << pieces;
    EXPECT_EQ(h.shape.boundary_loops, 2) << pieces;
    EXPECT_EQ(h.shape.euler_characteristic, 2) << pieces;
    EXPECT_EQ(h.shape.seam_problem, "") << pieces;
    expect_same_shape(h.left_fold, h.shape, "two disks, one piece after another");
  }
}

// partition_piece(whole, pieces, piece) gives each of its points the span point_piece_spans gives
// it, for large pieces (a scan of the whole's points) and small ones (a sort of the piece's).
TEST(PieceSurface, PartitionedPiecesSpansAreTheWholeMeshs) {
  DatasetOptions o;
  o.cells = 3000;
  o.degree = 2;
  const MeshInput whole = shuffled(generate_dataset("random", o), 5);
  for (const int pieces : {1, 2, 3, 7, 16, 64}) {
    const auto spans = point_piece_spans(whole, pieces);
    for (int r = 0; r < pieces; ++r) {
      const MeshPiece piece = partition_piece(whole, pieces, r);
      const auto [begin, end] =
          piece_cell_range(static_cast<int64_t>(whole.num_cells()), pieces, r);
      const MeshPiece plain = extract_piece(whole, begin, end);
      ASSERT_EQ(piece.global_point, plain.global_point) << pieces << " " << r;
      EXPECT_EQ(piece.input.cell_nodes, plain.input.cell_nodes) << pieces << " " << r;
      EXPECT_EQ(piece.point_span, piece_point_spans(piece.global_point, spans))
          << pieces << " pieces, piece " << r;
    }
  }
}

} // namespace
} // namespace hoct
