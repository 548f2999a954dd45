// The Reeb graph (docs/ALGORITHM.md §8): the cut graph makes every component a disk, the exact
// Reeb graph of a linear field on a square annulus has its one loop between the hole's lowest and
// highest corners, the loops' essential pairs count the loops of every band of values (a brute
// force over random graphs), and two components give one graph each, by every method.
#include "analysis/tree_check.hpp"
#include "datasets/datasets.hpp"
#include "io/tree_json.hpp"
#include "mesh/cut_surface.hpp"
#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"
#include "pipeline/compute_tree.hpp"
#include "pipeline/threshold.hpp"
#include "tree/loop_pairs.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>

#include "test_meshes.hpp"

#include <cmath>
#include <map>
#include <random>

namespace hoct {
namespace {

// [0, 6]^2 in unit squares (two triangles each) of degree 1 or 2, without the squares of
// [2, 4]^2 (a square hole), the field f(x, y) at the nodes.
template <class F> MeshInput square_annulus(int degree, F f) {
  MeshInput in;
  in.source = "annulus";
  const int n = 6 * degree;
  auto id = [&](int i, int j) { return static_cast<int64_t>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = static_cast<double>(i) / degree, y = static_cast<double>(j) / degree;
      in.points.push_back({x, y, 0});
      in.values.push_back(f(x, y));
    }
  // A triangle of the lattice: corners (i, j) + degree * e_k, nodes in lattice order.
  auto triangle = [&](int i0, int j0, int di1, int dj1, int di2, int dj2) {
    std::vector<int64_t> nodes;
    for (int b = 0; b <= degree; ++b)
      for (int a = 0; a + b <= degree; ++a)
        nodes.push_back(id(i0 + a * di1 + b * di2, j0 + a * dj1 + b * dj2));
    in.add_cell(degree, nodes.data());
  };
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      if (i >= 2 && i < 4 && j >= 2 && j < 4)
        continue;
      const int x = i * degree, y = j * degree;
      triangle(x, y, 1, 0, 1, 1); // (x, y), (x+1, y), (x+1, y+1)
      triangle(x, y, 1, 1, 0, 1); // (x, y), (x+1, y+1), (x, y+1)
    }
  return in;
}

TEST(ReebGraph, TheCutMakesEveryComponentADisk) {
  for (int degree : {1, 2}) {
    const Mesh mesh = build_mesh(square_annulus(degree, [](double x, double y) { return x + y; }));
    const std::vector<int64_t> cut = cut_graph_edges(mesh.topology);
    ASSERT_FALSE(cut.empty());
    // A path from the hole to the outside: at most as long as the distance, a few edges.
    EXPECT_LE(cut.size(), 6u);
    const CutSurface open = cut_open(mesh, cut);
    const Topology &t = open.mesh.topology;
    EXPECT_EQ(t.components(), 1);
    EXPECT_EQ(t.euler_characteristic(), 1);
    EXPECT_EQ(t.boundary_loops(), 1);
    EXPECT_EQ(open.seams.size(), cut.size());
    EXPECT_EQ(t.num_vertices(),
              mesh.topology.num_vertices() + static_cast<int64_t>(cut.size()) + 1);
  }
  // A disk and a sphere need no cut.
  for (const char *name : {"heater", "sphere"})
    EXPECT_TRUE(cut_graph_edges(build_mesh(generate_dataset(name, {})).topology).empty()) << name;
}

TEST(ReebGraph, ALinearFieldOnASquareAnnulusHasOneLoopAroundTheHole) {
  for (int degree : {1, 2}) {
    const Mesh mesh =
        build_mesh(square_annulus(degree, [](double x, double y) { return x + 0.3 * y; }));
    TreeRequest rq;
    const TreeOutcome out = compute_tree(mesh, rq);
    const TreeResult &g = out.tree;
    EXPECT_TRUE(out.warnings.empty());
    EXPECT_TRUE(g.reeb_graph);
    EXPECT_EQ(g.loops, 1);
    ASSERT_EQ(g.nodes.size(), 4u) << degree;
    ASSERT_EQ(g.arcs.size(), 4u);
    // The minimum (0,0), the hole's lowest corner (2,2) where the level sets part around it, its
    // highest corner (4,4) where they meet again, the maximum (6,6); two arcs between the saddles.
    const double want[4] = {0, 2.6, 5.2, 7.8};
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(g.nodes[i].value, want[i], 1e-12) << i;
    EXPECT_EQ(g.nodes[1].type, NodeType::Saddle);
    EXPECT_EQ(g.nodes[2].type, NodeType::Saddle);
    std::map<std::array<int64_t, 2>, int> count;
    for (const auto &a : g.arcs)
      ++count[a];
    EXPECT_EQ((count[{1, 2}]), 2);
    // The loop's essential pair: top 5.2, bottom 2.6.
    int loop_pairs_seen = 0;
    for (const auto &p : g.pairs)
      if (p.kind == PersistencePair::Kind::Loop) {
        ++loop_pairs_seen;
        EXPECT_NEAR(p.birth_value, 5.2, 1e-12);
        EXPECT_NEAR(p.death_value, 2.6, 1e-12);
      }
    EXPECT_EQ(loop_pairs_seen, 1);
    const TreeCheckReport r = check_tree(g, mesh, {});
    EXPECT_TRUE(r.ok()) << r.summary(10);
    // Drawn on the surface, the loop's two arcs go round the hole on either side: one through
    // the corner (4, 2) (x - y > 0 along it), the other through (2, 4).
    TreeRequest drawn;
    drawn.arcs = ArcGeometry::Paths;
    const TreeResult d = compute_tree(mesh, drawn).tree;
    ASSERT_EQ(d.arc_paths.size(), d.arcs.size());
    std::vector<double> side;
    for (std::size_t k = 0; k < d.arcs.size(); ++k)
      if (d.arcs[k] == std::array<int64_t, 2>{1, 2}) {
        double sum = 0;
        for (const Vec3 &q : d.arc_paths[k])
          sum += q[0] - q[1];
        side.push_back(sum / static_cast<double>(d.arc_paths[k].size()));
      }
    ASSERT_EQ(side.size(), 2u);
    EXPECT_LT(std::min(side[0], side[1]), -0.5);
    EXPECT_GT(std::max(side[0], side[1]), 0.5);
  }
}

TEST(ReebGraph, AWavyFieldOnTheAnnulusPassesTheChecker) {
  const Mesh mesh = build_mesh(square_annulus(2, [](double x, double y) {
    return std::sin(1.3 * x + 0.2) * std::cos(0.9 * y - 0.4) + 0.05 * x;
  }));
  const TreeOutcome out = compute_tree(mesh, {});
  EXPECT_TRUE(out.tree.reeb_graph);
  EXPECT_LE(out.tree.loops, 1);
  const TreeCheckReport r = check_tree(out.tree, mesh, {});
  EXPECT_TRUE(r.ok()) << r.summary(10);
  // Simplification prunes leaves, never a loop: the simplified graph keeps its loops and passes.
  TreeRequest rq;
  rq.simplify = parse_threshold("20%");
  const TreeOutcome s = compute_tree(mesh, rq);
  ASSERT_TRUE(s.simplified);
  EXPECT_LT(s.simplified->nodes.size(), out.tree.nodes.size());
  EXPECT_EQ(s.simplified->loops, out.tree.loops);
  EXPECT_TRUE(s.simplified->reeb_graph);
  const TreeCheckReport rs = check_tree(*s.simplified, mesh, {});
  EXPECT_TRUE(rs.ok()) << rs.summary(10);
}

TEST(ReebGraph, TwoComponentsGiveTwoGraphsByEveryMethod) {
  MeshInput two;
  two.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  two.values = {0, 1, 2, 3, 4, 5};
  const int64_t a[3] = {0, 1, 2}, b[3] = {3, 4, 5};
  two.add_cell(1, a);
  two.add_cell(1, b);
  const Mesh mesh = build_mesh(two);
  const TreeOutcome out = compute_tree(mesh, {});
  EXPECT_TRUE(out.warnings.empty());
  EXPECT_TRUE(out.tree.reeb_graph);
  EXPECT_EQ(out.tree.loops, 0);
  EXPECT_EQ(out.tree.nodes.size(), 4u);
  EXPECT_EQ(out.tree.arcs.size(), 2u);
  // The piecewise-linear methods compute the same graph (a linear field: their nodes are its).
  TreeRequest refined;
  refined.method = TreeMethod::Refine;
  refined.refine = 2;
  const TreeOutcome pl = compute_tree(mesh, refined);
  EXPECT_TRUE(pl.warnings.empty());
  EXPECT_TRUE(pl.tree.reeb_graph);
  EXPECT_EQ(pl.tree.loops, 0);
  ASSERT_EQ(pl.tree.nodes.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(pl.tree.nodes[i].value, out.tree.nodes[i].value);
  EXPECT_EQ(pl.tree.arcs, out.tree.arcs);
}

// Quadrilaterals of an nu x nv grid wrapped in u (and in v for a torus; twisted once in u for a
// Moebius strip, whose v runs 0..nv), two triangles each, linear, on the surface in 3D.
MeshInput wrapped_grid(int nu, int nv, bool torus, bool twist) {
  return testing::surface_grid(nu, nv, true, torus, twist,
                               [](const Vec3 &p) { return p[0] + 0.1 * p[2]; });
}

// Topology::cut_open, which derives the cut topology, gives what building it from the cut
// corners gives: every vertex, edge (in the same order), incidence, orientation and count.
TEST(ReebGraph, TheDerivedCutTopologyIsTheBuiltOne) {
  DatasetOptions plate;
  plate.cells = 2000;
  plate.degree = 1;
  const std::vector<std::pair<std::string, MeshInput>> meshes = {
      {"annulus", square_annulus(1, [](double x, double y) { return x + y; })},
      {"torus", wrapped_grid(12, 8, true, false)},
      {"moebius", wrapped_grid(16, 3, false, true)},
      {"plate", generate_dataset("plate", plate)}};
  for (const auto &[name, input] : meshes) {
    ProblemLog problems;
    const Topology t = Topology::build(input, problems);
    const std::vector<int64_t> cut = cut_graph_edges(t);
    ASSERT_FALSE(cut.empty()) << name;
    const CornerCut corners = cut_corners(t, cut);
    std::vector<uint8_t> is_cut(static_cast<std::size_t>(t.num_edges()), 0);
    for (int64_t e : cut)
      is_cut[e] = 1;
    const int64_t nv = static_cast<int64_t>(corners.vertex_origin.size());
    std::vector<int64_t> edge_origin;
    const Topology derived = t.cut_open(corners.first, corners.split_corners, is_cut, &edge_origin);
    const std::vector<int64_t> corner_vertex = corner_vertices(t, corners);
    MeshInput cut_input;
    cut_input.points.resize(static_cast<std::size_t>(nv));
    for (int64_t c = 0; c < t.num_cells(); ++c)
      cut_input.add_cell(1, &corner_vertex[3 * c]);
    ProblemLog cut_problems;
    const Topology built = Topology::build(cut_input, cut_problems);
    EXPECT_FALSE(cut_problems.has_errors()) << name << cut_problems.summary();
    ASSERT_EQ(derived.num_vertices(), built.num_vertices()) << name;
    ASSERT_EQ(derived.num_edges(), built.num_edges()) << name;
    for (int64_t v = 0; v < nv; ++v) {
      EXPECT_EQ(derived.vertex_point(v), built.vertex_point(v)) << name;
      EXPECT_EQ(derived.vertex_cell(v), built.vertex_cell(v)) << name;
      EXPECT_EQ(derived.vertex_corner(v), built.vertex_corner(v)) << name;
    }
    for (int64_t e = 0; e < built.num_edges(); ++e) {
      EXPECT_EQ(derived.edge_vertices(e), built.edge_vertices(e)) << name << " edge " << e;
      ASSERT_EQ(derived.edge_cell_count(e), built.edge_cell_count(e)) << name << " edge " << e;
      for (int i = 0; i < built.edge_cell_count(e); ++i)
        EXPECT_EQ(derived.edge_cells_begin(e)[i], built.edge_cells_begin(e)[i]) << name;
    }
    // Each edge of the cut copies the original edge between its vertices' originals, and each
    // cell's edges copy the cell's original edges.
    ASSERT_EQ(edge_origin.size(), static_cast<std::size_t>(built.num_edges())) << name;
    for (int64_t e = 0; e < built.num_edges(); ++e)
      for (int i = 0; i < 2; ++i)
        EXPECT_EQ(corners.vertex_origin[derived.edge_vertices(e)[i]],
                  t.edge_vertices(edge_origin[e])[i])
            << name << " edge " << e;
    for (int64_t c = 0; c < t.num_cells(); ++c) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(edge_origin[derived.cell_edge(c, k)], t.cell_edge(c, k)) << name;
        EXPECT_EQ(corners.corner_vertex(t, c, k), corner_vertex[3 * c + k]) << name;
      }
      EXPECT_EQ(derived.cell_vertices(c), built.cell_vertices(c)) << name;
      EXPECT_EQ(derived.cell_parity(c), built.cell_parity(c)) << name << " cell " << c;
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(derived.cell_edge(c, k), built.cell_edge(c, k)) << name;
        EXPECT_EQ(derived.edge_reversed(c, k), built.edge_reversed(c, k)) << name;
      }
    }
    EXPECT_EQ(derived.boundary_edges(), built.boundary_edges()) << name;
    EXPECT_EQ(derived.boundary_loops(), built.boundary_loops()) << name;
    EXPECT_EQ(derived.components(), built.components()) << name;
    EXPECT_EQ(derived.orientable(), built.orientable()) << name;
    EXPECT_EQ(derived.euler_characteristic(), 1) << name;
    EXPECT_EQ(derived.boundary_loops(), 1) << name;
  }
  // The strip is non-orientable and its cut is not; the torus has genus 1.
  ProblemLog p1, p2;
  EXPECT_FALSE(Topology::build(wrapped_grid(16, 3, false, true), p1).orientable());
  EXPECT_EQ(Topology::build(wrapped_grid(12, 8, true, false), p2).euler_characteristic(), 0);
}

// The checker counts loops: an extra parallel arc is a second loop the annulus does not allow,
// a recorded count that differs from the arcs' fails, and a cycle on a disk is no contour tree.
TEST(ReebGraph, TheCheckerCountsLoops) {
  const Mesh mesh = build_mesh(square_annulus(1, [](double x, double y) { return x + 0.3 * y; }));
  const TreeResult g = compute_tree(mesh, {}).tree;
  ASSERT_EQ(g.loops, 1);
  auto failures = [&](const TreeResult &t, const Mesh &m) {
    std::string all;
    for (const auto &f : check_tree(t, m, {}).failures)
      all += "[" + f.check + "] " + f.message + "\n";
    return all;
  };
  TreeResult extra = g;
  extra.arcs.push_back({1, 2});
  std::sort(extra.arcs.begin(), extra.arcs.end());
  extra.nodes[1].up = extra.nodes[2].down = 0; // let the checker count the degrees
  extra.loops = 2;
  EXPECT_NE(failures(extra, mesh).find("at most 1"), std::string::npos) << failures(extra, mesh);
  TreeResult miscounted = g;
  miscounted.loops = 0;
  EXPECT_NE(failures(miscounted, mesh).find("but it records 0"), std::string::npos);
  // The same graph on the mesh without its hole (a disk): a cycle is not allowed there.
  const Mesh disk = build_mesh(generate_dataset("gauss", {}));
  TreeResult cyclic = compute_tree(disk, {}).tree;
  ASSERT_GE(cyclic.nodes.size(), 3u);
  cyclic.arcs.push_back(cyclic.arcs.front());
  cyclic.loops = 1;
  EXPECT_NE(failures(cyclic, disk).find("closes a cycle"), std::string::npos);
}

// Brute force: for every band [t, s] of node indices, the loop pairs with top <= s and bottom
// >= t number the independent loops of the arcs with both ends in the band.
TEST(ReebGraph, LoopPairsCountTheLoopsOfEveryBand) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 10);
    ContourTree g;
    for (int i = 0; i < n; ++i) {
      g.nodes.push_back(i);
      g.values.push_back(i);
    }
    const int m = static_cast<int>(rng() % (2 * n)) + 1;
    for (int k = 0; k < m; ++k) {
      int64_t x = rng() % n, y = rng() % n;
      if (x == y)
        continue;
      g.arcs.push_back({std::min(x, y), std::max(x, y)});
    }
    std::sort(g.arcs.begin(), g.arcs.end());
    const std::vector<PersistencePair> pairs = loop_pairs(g);
    EXPECT_EQ(static_cast<int64_t>(pairs.size()), graph_loops(g));
    for (int t = 0; t < n; ++t)
      for (int s = t; s < n; ++s) {
        ContourTree band;
        band.nodes = g.nodes;
        band.values = g.values;
        for (const auto &a : g.arcs)
          if (a[0] >= t && a[1] <= s)
            band.arcs.push_back(a);
        int64_t counted = 0;
        for (const auto &p : pairs)
          counted += p.birth <= s && p.death >= t;
        ASSERT_EQ(counted, graph_loops(band)) << "trial " << trial << " band " << t << ".." << s;
      }
  }
}

// compute_tree consuming the mesh and the input (the CLI's --linear: the mesh released before the
// PL tree, the input once split) gives the result of the call that keeps them, byte for byte,
// on a disk, a sphere and an annulus (a Reeb graph), by the linear and the exact method.
TEST(ReebGraph, ComputeTreeConsumingTheMeshGivesTheSameResult) {
  std::vector<MeshInput> inputs = {generate_dataset("gauss", {}), generate_dataset("sphere", {}),
                                   square_annulus(2, [](double x, double y) {
                                     return std::sin(1.3 * x + 0.2) * std::cos(0.9 * y - 0.4);
                                   })};
  for (std::size_t k = 0; k < inputs.size(); ++k)
    for (const TreeMethod method : {TreeMethod::Linear, TreeMethod::Exact}) {
      TreeRequest rq;
      rq.method = method;
      rq.simplify = parse_threshold("1%");
      const Mesh kept = build_mesh(inputs[k]);
      const TreeOutcome want = compute_tree(kept, rq, &inputs[k]);
      MeshInput input = inputs[k];
      const TreeOutcome got = compute_tree(build_mesh(inputs[k]), rq, std::move(input));
      EXPECT_EQ(tree_to_json(got.tree, false), tree_to_json(want.tree, false)) << k;
      ASSERT_TRUE(got.simplified && want.simplified);
      EXPECT_EQ(tree_to_json(*got.simplified, false), tree_to_json(*want.simplified, false)) << k;
      EXPECT_EQ(got.tree.reeb_graph, k == 2) << k;
      if (method == TreeMethod::Linear) { // both released
        EXPECT_TRUE(input.points.empty() && input.values.empty()) << k;
      }
    }
}

} // namespace
} // namespace hoct
