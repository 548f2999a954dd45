// The arcs of a partitioned mesh's tree drawn by its pieces (exact/piece_arcs), against the whole
// mesh's graph (the exact one, and the refine method's PL mesh): cut into 1-7 pieces, each arc must
// run from its lower node to its upper node through points no farther apart than a cell, and be
// drawn within its values exactly where a search of the whole mesh's graph finds a path within them
// (the pieces' graphs, joined at the nodes they share, are the whole's).
#include "datasets/datasets.hpp"
#include "exact/exact_contour_tree.hpp"
#include "exact/piece_arc_rounds.hpp"
#include "exact/piece_trees.hpp"
#include "exact/pl_piece_trees.hpp"
#include "exact/pl_reeb_pieces.hpp"
#include "exact/reeb_group.hpp"
#include "exact/reeb_pieces.hpp"
#include "mesh/cut_surface.hpp"
#include "mesh/mesh.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/refinement.hpp"
#include "util/byte_codec.hpp"

#include "test_pieces.hpp"
#include "test_same_tree.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace hoct {
namespace {

double distance(const Vec3 &a, const Vec3 &b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// By the exact method, or (refine > 0) the refine method's PL mesh of K = refine, or (reeb) the
// exact Reeb graph of a surface cut open (the pieces' groups glued: exact/reeb_group).
void check_arcs(const MeshInput &whole, const std::string &name, int refine = 0,
                bool reeb = false) {
  MeshScales scales;
  MeshBuildOptions bo;
  bo.throw_on_error = false;
  bo.whole_scales = [&](const MeshScales &own) { return scales = own; };
  const Mesh mesh = build_mesh(whole, bo);
  ExactTreeOptions eo;
  eo.threads = 1;
  eo.arc_geometry = true;
  std::optional<CutSurface> cut;
  if (reeb) {
    cut = cut_open(mesh, cut_graph_edges(mesh.topology));
    eo.cut = &*cut;
  }
  TreeResult expected =
      refine > 0 ? pl_contour_tree(hoct::refine(mesh, refine), false, "refine", true, 1, reeb)
                 : exact_contour_tree(reeb ? cut->mesh : mesh, eo);
  for (TreeNode &n : expected.nodes) // the input's cells, as the pieces report them
    if (!mesh.origins.identity()) {
      const CellPlace p = mesh.origins.to_input(n.cell, n.uv);
      n.cell = p.cell;
      n.uv = p.uv;
    }
  ASSERT_TRUE(expected.graph) << name;
  const GeometricGraph &g = *expected.graph;
  // The largest step a path takes: across a cell.
  double step = 0;
  for (std::size_t c = 0; c < whole.num_cells(); ++c) {
    for (int64_t i = whole.cell_offsets[c]; i < whole.cell_offsets[c + 1]; ++i)
      for (int64_t j = whole.cell_offsets[c]; j < i; ++j)
        step = std::max(
            step, distance(whole.points[whole.cell_nodes[i]], whole.points[whole.cell_nodes[j]]));
  }
  for (const int pieces : {1, 2, 3, 4, 7}) {
    const std::string what = name + ", " + std::to_string(pieces) + " pieces";
    std::vector<PieceArcGraph> graphs;
    std::vector<ReebGroup> pl_glued;
    double reference = 0;
    std::vector<PieceTrees> groups = testing::pieces_of(
        whole, pieces, scales, false, reference,
        [&](const Mesh &m, const PiecePlace &p, const ExactTreeOptions &o, TreeTimings &time) {
          graphs.emplace_back();
          if (refine > 0 && reeb) { // the PL mesh cut into disks: its group
            pl_glued.push_back(
                pl_reeb_group(refined_piece_mesh(m, p, refine), p, false, 1, &graphs.back()));
            return PieceTrees{};
          }
          return refine > 0 ? refined_piece_trees(m, p, refine, false, 1, &graphs.back()).trees
                 : reeb     ? reeb_piece(m, p, o, time, &graphs.back())
                            : piece_trees(m, p, o, time, &graphs.back());
        });
    std::vector<ReebGroup> glued;
    for (std::size_t p = 0; p < groups.size(); ++p)
      glued.push_back(!reeb        ? ReebGroup{}
                      : refine > 0 ? pl_glued[p]
                                   : reeb_group(groups[p], false));
    for (int s = 1; s < pieces; s *= 2)
      for (int r = 0; r + s < pieces; r += 2 * s)
        if (reeb)
          glued[r] = merge_reeb_groups(glued[r], glued[r + s], false);
        else
          groups[r] = merge_piece_trees(groups[r], groups[r + s], false);
    const TreeResult tree = reeb ? reeb_graph_of_group(glued[0], false, reference)
                                 : tree_of_pieces(groups[0], false, reference);
    // With the graph's geometry the pieces' trees are still the whole's.
    testing::expect_same_graph(tree, expected, what);
    int32_t parallel_groups = 0;
    const std::vector<ArcEnds> arcs = tree_arc_ends(
        tree, reeb ? std::span<const PieceNode>(glued[0].nodes) : groups[0].nodes, parallel_groups);
    if (reeb) {
      EXPECT_GT(parallel_groups, 0) << what; // loops: parallel arcs
    }
    std::vector<PieceArcGraph *> local;
    for (PieceArcGraph &p : graphs)
      local.push_back(&p);
    InProcessLinks links(pieces);
    ArcPathCounts counts;
    std::vector<ArcDrawn> how;
    const std::vector<std::vector<Vec3>> paths =
        draw_arcs_by_pieces(local, arcs, links, 1, &counts, &how);
    int64_t crossing = 0;
    GeometricGraph::Search s;
    for (std::size_t i = 0; i < arcs.size(); ++i) {
      const std::string arc = what + ", arc " + std::to_string(i);
      const int64_t a = expected.nodes[tree.arcs[i][0]].graph_node,
                    b = expected.nodes[tree.arcs[i][1]].graph_node;
      g.band_path(a, b, g.value(a), g.value(b), GeometricGraph::kMaxVisits, s);
      const bool band = !s.nodes.empty();
      // (Not on a plateau's arcs of zero length: a piece without the fallback cell beyond its
      // edge joins the edge's ends directly, where the whole mesh's graph passes through the
      // cell's lattice nodes, whose values may round apart. finish_tree contracts those arcs.
      // Nor a higher level of parallel arcs: it avoids its lower levels' paths.)
      if (arcs[i].lo < arcs[i].hi && arcs[i].level == 0) {
        EXPECT_EQ(how[i].round == static_cast<int>(ArcRound::Band), band)
            << arc << " drawn in round " << how[i].round;
      }
      if (arcs[i].level == 0) // the join tree joins the ends below the upper one
        EXPECT_LE(how[i].round, static_cast<int>(ArcRound::Below)) << arc;
      else
        EXPECT_LT(how[i].round, kArcRounds) << arc;
      crossing += how[i].across && how[i].round == static_cast<int>(ArcRound::Band);
      const std::vector<Vec3> &p = paths[i];
      ASSERT_GE(p.size(), 2u) << arc;
      const double tolerance = 1e-9 * (1 + step);
      EXPECT_LE(distance(p.front(), tree.nodes[tree.arcs[i][0]].position), tolerance) << arc;
      EXPECT_LE(distance(p.back(), tree.nodes[tree.arcs[i][1]].position), tolerance) << arc;
      for (std::size_t k = 1; k < p.size(); ++k)
        ASSERT_LE(distance(p[k - 1], p[k]), step * (1 + 1e-9)) << arc << " point " << k;
    }
    // Parallel arcs go around their hole on different sides: no point inside one is inside a
    // lower level's.
    for (std::size_t i = 0; i < arcs.size(); ++i)
      for (std::size_t j = 0; j < arcs.size(); ++j) {
        if (arcs[i].group < 0 || arcs[j].group != arcs[i].group || arcs[j].level >= arcs[i].level)
          continue;
        const std::vector<Vec3> &p = paths[i], &q = paths[j];
        for (std::size_t a = 1; a + 1 < p.size(); ++a)
          for (std::size_t b = 1; b + 1 < q.size(); ++b)
            ASSERT_GT(distance(p[a], q[b]), 1e-12 * step)
                << what << ": parallel arcs " << j << " and " << i << " meet inside";
      }
    // Arcs drawn within their values across pieces (one piece draws them all itself).
    if (pieces == 1)
      EXPECT_EQ(crossing, 0) << what;
    else
      EXPECT_GT(crossing, 0) << what;
  }
}

TEST(PieceArcs, ArcsAreDrawnThroughThePiecesWithinTheirValuesWhereTheWholeGraphIs) {
  for (const std::string name : {"gauss", "heater", "conductor", "sphere"}) {
    DatasetOptions o;
    o.cells = name == "heater" ? 1500 : name == "conductor" ? 1200 : 3000;
    check_arcs(generate_dataset(name, o), name);
  }
}

TEST(PieceArcs, ThePlMethodsArcsToo) {
  for (const std::string name : {"heater", "sphere"}) {
    DatasetOptions o;
    o.cells = 800;
    check_arcs(generate_dataset(name, o), name + " refined K = 2", 2);
  }
  DatasetOptions o;
  o.cells = 1500;
  o.plateau = 30;
  check_arcs(generate_dataset("random", o), "random with a plateau refined K = 1", 1);
}

TEST(PieceArcs, AReebGraphsParallelArcsGoAroundTheirHoles) {
  DatasetOptions o;
  o.cells = 3000;
  check_arcs(generate_dataset("plate", o), "plate", 0, true);
  o.cells = 1500;
  check_arcs(generate_dataset("plate", o), "plate refined K = 2", 2, true);
}

TEST(PieceArcs, NoisyFieldsPlateausAndCurvedCells) {
  DatasetOptions o;
  o.cells = 3000;
  check_arcs(generate_dataset("random", o), "random");
  o.plateau = 30; // fallback cells across the pieces, lattice nodes on their shared edges
  check_arcs(generate_dataset("random", o), "random with a plateau");
  DatasetOptions q;
  q.cells = 800;
  q.quadrilaterals = true;
  check_arcs(generate_dataset("random", q), "random quadrilaterals");
}

TEST(PieceArcs, BytesThatAreNotReportsOrStretchesAreRefused) {
  const std::vector<ArcEnds> arcs(2);
  const std::vector<int64_t> which{0};
  std::vector<uint8_t> routed;
  const std::vector<std::vector<std::byte>> junk{std::vector<std::byte>(5)};
  EXPECT_THROW(route_arcs(junk, which, arcs, routed), std::runtime_error);
  EXPECT_THROW(decode_stretches(junk[0]), std::runtime_error);
  std::vector<std::vector<Vec3>> paths(2);
  EXPECT_THROW(join_stretches(junk, paths), std::runtime_error);
  PieceArcGraph none;
  none.index_keys();
  EXPECT_THROW(meet_neighbours(none, junk), std::runtime_error);
  // One piece's report: `count` components, the ends' components, and a touch (piece, theirs,
  // mine) of a neighbour's.
  auto report = [](int32_t count, std::array<int32_t, 2> ends, std::vector<int32_t> touch) {
    ByteWriter w;
    w.value<int32_t>(0);
    w.array(std::vector<int32_t>{count});
    w.array(std::vector<std::array<int32_t, 2>>{ends});
    w.array(std::vector<int64_t>{0, touch.empty() ? 0 : 1});
    std::vector<int32_t> record(12, 0); // a NodeKey, then piece, theirs, mine, unused
    std::copy(touch.begin(), touch.end(), record.begin() + 8);
    w.value<uint64_t>(touch.empty() ? 0 : 1);
    if (!touch.empty()) {
      const auto *b = reinterpret_cast<const std::byte *>(record.data());
      w.out.insert(w.out.end(), b, b + record.size() * sizeof(int32_t));
    }
    return std::vector<std::vector<std::byte>>{w.out};
  };
  EXPECT_NO_THROW(route_arcs(report(1, {0, 0}, {}), which, arcs, routed));
  EXPECT_EQ(routed, std::vector<uint8_t>{1}); // both ends in its one component
  EXPECT_THROW(route_arcs(report(1, {1, 0}, {}), which, arcs, routed), std::runtime_error);
  EXPECT_THROW(route_arcs(report(1, {0, -1}, {0, 3, 0}), which, arcs, routed), std::runtime_error);
  EXPECT_NO_THROW(route_arcs(report(1, {0, -1}, {0, 0, 0}), which, arcs, routed));
  EXPECT_EQ(routed, std::vector<uint8_t>{0}); // no component with the upper end
}

} // namespace
} // namespace hoct
