#include "bench_pieces.hpp"

#include "bench_support.hpp"

#include "datasets/datasets.hpp"
#include "exact/piece_codec.hpp"
#include "exact/piece_trees.hpp"
#include "exact/reeb_group.hpp"
#include "exact/reeb_pieces.hpp"
#include "mesh/duplicate_points.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/mesh_partition.hpp"
#include "mesh/piece_surface.hpp"
#include "mesh/topology.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace hoct::bench {

namespace {

// A Reeb graph's groups (exact/reeb_group): the plate with 100 holes, half the size's cells, in
// strips of contiguous cells; each piece's group through bytes as a rank sends it, merged in the
// binary tree of ranks; against what rank 0 would hold if it gathered every piece's kept trees.
void reeb_groups_table(const std::vector<double> &sizes) {
  std::printf("## A Reeb graph's pieces glued in the tree of ranks (the plate with 100 holes, "
              "cubic, in strips of contiguous cells, 1 thread; per piece: the mean; merge: the "
              "longest merge of each level, summed; largest group: the largest message a merge "
              "received; gathered: every piece's kept trees, what rank 0 would receive without "
              "the tree)\n\n");
  std::printf("| cells | pieces | cut and kept trees per piece (s) | kept nodes per piece | "
              "group per piece (s) | group bytes per piece | merges, all levels (s) | largest "
              "group received (bytes) | last group's nodes | rank 0's finish (s) | gathered "
              "instead (bytes) | loops |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (double size : sizes) {
    DatasetOptions o;
    o.cells = static_cast<long long>(size / 2);
    o.degree = 3;
    const MeshInput whole = generate_dataset("plate", o);
    const int64_t cells = static_cast<int64_t>(whole.num_cells());
    MeshScales scales;
    {
      MeshBuildOptions bo;
      bo.whole_scales = [&](const MeshScales &own) { return scales = own; };
      (void)build_mesh(whole, bo);
    }
    for (int pieces : {2, 8, 32, 128}) {
      std::vector<ReebGroup> groups;
      double trees = 0, kept = 0, grouping = 0, bytes = 0, gathered = 0;
      const auto spans = point_piece_spans(whole, pieces);
      for (int r = 0; r < pieces; ++r) {
        const auto [begin, end] = piece_cell_range(cells, pieces, r);
        const MeshPiece piece = extract_piece(whole, begin, end);
        MeshBuildOptions bo;
        bo.throw_on_error = false;
        bo.whole_scales = [&](const MeshScales &) { return scales; };
        const Mesh mesh = build_mesh(piece.input, bo);
        const auto piece_spans = piece_point_spans(piece.global_point, spans);
        const PiecePlace place{r, piece.global_point, begin, triangles_before(whole, begin),
                               piece_spans};
        ExactTreeOptions eo;
        eo.threads = 1;
        TreeTimings time;
        const auto t0 = clock_type::now();
        const PieceTrees t = reeb_piece(mesh, place, eo, time);
        trees += seconds_since(t0);
        kept += static_cast<double>(t.nodes.size());
        gathered += static_cast<double>(encode_piece_trees(t).size());
        const auto t1 = clock_type::now();
        ReebGroup g = reeb_group(t, false);
        grouping += seconds_since(t1);
        const std::vector<std::byte> b = encode_reeb_group(g);
        bytes += static_cast<double>(b.size());
        groups.push_back(decode_reeb_group(b));
      }
      double merge = 0, largest = 0;
      for (int step = 1; step < pieces; step *= 2) {
        double longest = 0;
        for (int r = 0; r + step < pieces; r += 2 * step) {
          const std::vector<std::byte> b = encode_reeb_group(groups[r + step]);
          largest = std::max(largest, static_cast<double>(b.size()));
          const auto t0 = clock_type::now();
          groups[r] = merge_reeb_groups(groups[r], decode_reeb_group(b), false);
          longest = std::max(longest, seconds_since(t0));
        }
        merge += longest;
      }
      const auto t2 = clock_type::now();
      const TreeResult graph = reeb_graph_of_group(groups.front(), false, 0.0);
      const double finish = seconds_since(t2);
      std::printf("| %lld | %d | %.4f | %.0f | %.4f | %.0f | %.4f | %.0f | %zu | %.4f | %.0f | "
                  "%lld |\n",
                  static_cast<long long>(cells), pieces, trees / pieces, kept / pieces,
                  grouping / pieces, bytes / pieces, merge, largest, groups.front().nodes.size(),
                  finish, gathered, static_cast<long long>(graph.loops));
      std::fflush(stdout);
    }
  }
  std::printf("\n");
}

} // namespace

void pieces_section(const std::vector<double> &sizes, int runs) {
  std::printf("## The distributed tree's phases, piece by piece in one process (random cubic "
              "fields, 1 thread; per piece: the mean over the pieces; merge: the longest merge "
              "of each level of the binary reduction, summed over the levels; the surface "
              "summaries' merges alike, and the largest summary a merge received)\n\n");
  std::printf(
      "| cells | pieces | whole topology, rank 0 alone (s) | whole duplicates, rank 0 "
      "alone (s) | extract + build per piece (s) | surface summary per piece (s) | seam "
      "bytes per piece | summaries' merges, all levels (s) | largest summary received (bytes) "
      "| kept trees per piece (s) | kept nodes per piece | bytes per piece | bytes per node "
      "| merge, all levels (s) | levels |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (double size : sizes) {
    DatasetOptions o;
    o.cells = static_cast<long long>(size);
    o.degree = 3;
    const MeshInput whole = generate_dataset("random", o);
    const int64_t cells = static_cast<int64_t>(whole.num_cells());
    // Rank 0's checks of the whole mesh alone (distributed/distributed_tree: only where the
    // pieces found a problem), for comparison with the pieces' summaries and their glue.
    std::vector<double> topo_s, dup_s;
    for (int i = 0; i < runs; ++i) {
      ProblemLog problems;
      const auto t0 = clock_type::now();
      const Topology topo = Topology::build(whole, problems, 1);
      topo_s.push_back(seconds_since(t0));
      const auto t1 = clock_type::now();
      const auto box = bounding_box(whole.points, 1);
      check_duplicate_vertices(whole, topo, problems, 1, &box);
      dup_s.push_back(seconds_since(t1));
    }
    for (int pieces : {2, 8, 32, 128}) {
      std::vector<PieceTrees> groups;
      std::vector<PieceSurface> surfaces;
      double build = 0, summary = 0, seam_bytes = 0, trees = 0, kept = 0, bytes = 0;
      for (int r = 0; r < pieces; ++r) {
        const auto [begin, end] = piece_cell_range(cells, pieces, r);
        // As a rank does (distributed/distributed_tree): its cells and their spans, the mesh
        // built with its open points.
        const auto t0 = clock_type::now();
        const MeshPiece piece = partition_piece(whole, pieces, r);
        std::vector<uint8_t> open(piece.point_span.size());
        for (std::size_t i = 0; i < open.size(); ++i)
          open[i] = piece.point_span[i][0] != piece.point_span[i][1];
        MeshBuildOptions bo;
        bo.throw_on_error = false;
        bo.open_points = open;
        const Mesh mesh = build_mesh(piece.input, bo);
        build += seconds_since(t0);
        const auto ts = clock_type::now();
        surfaces.push_back(summarize_piece(mesh.topology, piece.global_point, piece.point_span, r));
        summary += seconds_since(ts);
        seam_bytes += static_cast<double>(encode_piece_surface(surfaces.back()).size());
        const auto t1 = clock_type::now();
        const PiecePlace place{r, piece.global_point, begin, triangles_before(whole, begin),
                               piece.point_span};
        ExactTreeOptions eo;
        TreeTimings time;
        PieceTrees t = piece_trees(mesh, place, eo, time);
        trees += seconds_since(t1);
        kept += static_cast<double>(t.nodes.size());
        bytes += static_cast<double>(encode_piece_trees(t).size());
        groups.push_back(std::move(t));
      }
      // The summaries merged pairwise, as the ranks merge them (distributed/distributed_checks).
      double glue = 0, largest = 0;
      for (int step = 1; step < pieces; step *= 2) {
        double longest = 0;
        for (int r = 0; r + step < pieces; r += 2 * step) {
          largest = std::max(largest,
                             static_cast<double>(encode_piece_surface(surfaces[r + step]).size()));
          const auto t0 = clock_type::now();
          surfaces[r] = merge_piece_surfaces(surfaces[r], surfaces[r + step]);
          longest = std::max(longest, seconds_since(t0));
        }
        glue += longest;
      }
      const SurfaceShape shape = surface_shape(surfaces.front());
      if (!shape.seam_problem.empty() || shape.components != 1)
        throw std::runtime_error("the pieces' merged summaries do not give one clean surface: " +
                                 shape.seam_problem);
      double merge = 0;
      int levels = 0;
      for (int step = 1; step < pieces; step *= 2, ++levels) {
        double longest = 0;
        for (int r = 0; r + step < pieces; r += 2 * step) {
          const auto t0 = clock_type::now();
          groups[r] = merge_piece_trees(groups[r], groups[r + step], false);
          longest = std::max(longest, seconds_since(t0));
        }
        merge += longest;
      }
      std::printf("| %lld | %d | %.3f | %.3f | %.4f | %.4f | %.0f | %.4f | %.0f | %.4f | %.0f | "
                  "%.0f | %.0f | %.4f | %d |\n",
                  static_cast<long long>(cells), pieces, median(topo_s), median(dup_s),
                  build / pieces, summary / pieces, seam_bytes / pieces, glue, largest,
                  trees / pieces, kept / pieces, bytes / pieces, bytes / kept, merge, levels);
      std::fflush(stdout);
    }
  }
  std::printf("\n");
  reeb_groups_table(sizes);
}

} // namespace hoct::bench
