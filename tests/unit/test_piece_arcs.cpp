// The arcs of a partitioned mesh's tree drawn by its pieces (exact/piece_arcs), against the whole
// mesh's graph (the exact one, and the refine method's PL mesh): cut into 1-7 pieces, each arc must
// run from its lower node to its upper node through points no farther apart than a cell, and be
// drawn within its values exactly where a search of the whole mesh's graph finds a path within them
// (the pieces' graphs, joined at the nodes they share, are the whole's).
#include "datasets/datasets.hpp"
#include "exact/exact_contour_tree.hpp"
#include "exact/piece_arcs.hpp"
#include "exact/piece_trees.hpp"
#include "exact/pl_piece_trees.hpp"
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

// How each arc was drawn: the round (kArcRounds: straight), and whether across pieces.
constexpr int kStraight = kArcRounds;

// The pieces' steps run one piece after the other, as the ranks run them at once
// (distributed/distributed_arc_paths).
// What each piece sends each piece (out[from][to]), as each receives it (by sender).
std::vector<std::vector<std::vector<std::byte>>>
delivered(const std::vector<std::vector<std::vector<std::byte>>> &out) {
  std::vector<std::vector<std::vector<std::byte>>> in(out.size());
  for (std::size_t to = 0; to < out.size(); ++to)
    for (std::size_t from = 0; from < out.size(); ++from)
      in[to].push_back(out[from].size() > to ? out[from][to] : std::vector<std::byte>{});
  return in;
}

std::vector<std::vector<Vec3>> draw_by_pieces(std::vector<PieceArcGraph> &pieces,
                                              const std::vector<ArcEnds> &arcs,
                                              std::vector<int> &how, std::vector<uint8_t> &across) {
  const std::size_t n = arcs.size();
  const int count = static_cast<int>(pieces.size());
  std::vector<std::vector<std::vector<std::byte>>> offers;
  for (const PieceArcGraph &p : pieces)
    offers.push_back(border_offers(p, count));
  const auto offered = delivered(offers);
  for (std::size_t p = 0; p < pieces.size(); ++p)
    meet_neighbours(pieces[p], offered[p]);
  std::vector<std::vector<Vec3>> paths(n);
  how.assign(n, kStraight);
  across.assign(n, 0);
  for (int round = 0; round < kArcRounds; ++round) {
    const auto r = static_cast<ArcRound>(round);
    auto undrawn = [&] {
      std::vector<int64_t> which;
      for (std::size_t i = 0; i < n; ++i)
        if (paths[i].empty())
          which.push_back(static_cast<int64_t>(i));
      return which;
    };
    std::vector<int64_t> which = undrawn();
    if (r != ArcRound::Above)
      for (const PieceArcGraph &p : pieces) {
        const int64_t visits = r == ArcRound::Band ? GeometricGraph::kMaxVisits : 1024;
        std::vector<std::vector<Vec3>> local = draw_local_arcs(p, arcs, which, r, visits, 1);
        for (std::size_t k = 0; k < which.size(); ++k)
          if (paths[which[k]].empty() && !local[k].empty()) {
            paths[which[k]] = std::move(local[k]);
            how[which[k]] = round;
          }
      }
    which = undrawn();
    if (which.empty())
      break;
    std::vector<ArcComponents> components;
    std::vector<std::vector<std::vector<std::byte>>> labels;
    for (const PieceArcGraph &p : pieces) {
      components.push_back(piece_components(p, arcs, which, r));
      labels.push_back(neighbour_labels(p, components.back(), arcs, which, r));
    }
    const auto received = delivered(labels);
    std::vector<std::vector<std::byte>> reports;
    for (std::size_t p = 0; p < pieces.size(); ++p)
      reports.push_back(component_report(pieces[p], components[p], arcs, which, r, received[p]));
    std::vector<uint8_t> routed;
    const std::vector<std::vector<Stretch>> stretches = route_arcs(reports, which, arcs, routed);
    std::vector<std::vector<std::byte>> drawn;
    for (std::size_t p = 0; p < pieces.size(); ++p)
      drawn.push_back(
          draw_stretches(pieces[p], arcs, decode_stretches(encode_stretches(stretches[p])), r));
    join_stretches(drawn, paths);
    for (std::size_t k = 0; k < which.size(); ++k)
      if (routed[k]) {
        how[which[k]] = round;
        across[which[k]] = 1;
      }
  }
  return paths;
}

double distance(const Vec3 &a, const Vec3 &b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// By the exact method, or (refine > 0) the refine method's PL mesh of K = refine.
void check_arcs(const MeshInput &whole, const std::string &name, int refine = 0) {
  MeshScales scales;
  MeshBuildOptions bo;
  bo.throw_on_error = false;
  bo.whole_scales = [&](const MeshScales &own) { return scales = own; };
  const Mesh mesh = build_mesh(whole, bo);
  ExactTreeOptions eo;
  eo.threads = 1;
  eo.arc_geometry = true;
  TreeResult expected = refine > 0
                            ? pl_contour_tree(hoct::refine(mesh, refine), false, "refine", true, 1)
                            : exact_contour_tree(mesh, eo);
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
    double reference = 0;
    std::vector<PieceTrees> groups = testing::pieces_of(
        whole, pieces, scales, false, reference,
        [&](const Mesh &m, const PiecePlace &p, const ExactTreeOptions &o, TreeTimings &time) {
          graphs.emplace_back();
          return refine > 0 ? refined_piece_trees(m, p, refine, false, 1, &graphs.back()).trees
                            : piece_trees(m, p, o, time, &graphs.back());
        });
    for (int s = 1; s < pieces; s *= 2)
      for (int r = 0; r + s < pieces; r += 2 * s)
        groups[r] = merge_piece_trees(groups[r], groups[r + s], false);
    const TreeResult tree = tree_of_pieces(groups[0], false, reference);
    // With the graph's geometry the pieces' trees are still the whole's.
    testing::expect_same_graph(tree, expected, what);
    std::vector<ArcEnds> arcs;
    for (const auto &[lo, hi] : tree.arcs) {
      const PieceNode &x = groups[0].nodes[tree.nodes[lo].graph_node],
                      &y = groups[0].nodes[tree.nodes[hi].graph_node];
      arcs.push_back({x.key, y.key, x.value, y.value});
    }
    std::vector<int> how;
    std::vector<uint8_t> across;
    const std::vector<std::vector<Vec3>> paths = draw_by_pieces(graphs, arcs, how, across);
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
      // cell's lattice nodes, whose values may round apart. finish_tree contracts those arcs.)
      if (arcs[i].lo < arcs[i].hi) {
        EXPECT_EQ(how[i] == static_cast<int>(ArcRound::Band), band)
            << arc << " drawn by " << how[i];
      }
      EXPECT_NE(how[i], kStraight) << arc; // the join tree joins the ends below the upper one
      crossing += across[i] && how[i] == static_cast<int>(ArcRound::Band);
      const std::vector<Vec3> &p = paths[i];
      ASSERT_GE(p.size(), 2u) << arc;
      const double tolerance = 1e-9 * (1 + step);
      EXPECT_LE(distance(p.front(), tree.nodes[tree.arcs[i][0]].position), tolerance) << arc;
      EXPECT_LE(distance(p.back(), tree.nodes[tree.arcs[i][1]].position), tolerance) << arc;
      for (std::size_t k = 1; k < p.size(); ++k)
        ASSERT_LE(distance(p[k - 1], p[k]), step * (1 + 1e-9)) << arc << " point " << k;
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
