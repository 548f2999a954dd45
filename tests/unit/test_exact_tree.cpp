// The exact contour tree against fields with known critical points, the PL tree of a fine
// refinement, and the tree invariants.
#include "exact/exact_contour_tree.hpp"
#include "mesh/mesh.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/refinement.hpp"
#include "test_functions.hpp"
#include "test_meshes.hpp"
#include "tree/persistence.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace hoct {
namespace {

using testing::antiderivative_of_roots;
using testing::horner;
using testing::Rotation;

double stat(const TreeResult &t, const std::string &name) {
  for (const auto &[k, v] : t.stats.entries())
    if (k == name)
      return v;
  return -1;
}

// Independent check that a leaf is a local extremum of the piecewise field: sample every cell
// around the node (all cells at a vertex, both cells of an edge) on small circles in parameter
// space; a minimum must be below all samples, a maximum above.
void check_leaf_is_extremum(const TreeNode &n, const Mesh &m) {
  const Topology &topo = m.topology;
  std::vector<std::pair<int64_t, Vec2>> where; // (cell, uv of the node in that cell)
  const Vec2 corner[3] = {{0, 0}, {1, 0}, {0, 1}};
  if (n.location == NodeLocation::Interior) {
    where.push_back({n.cell, {n.uv[0], n.uv[1]}});
  } else if (n.location == NodeLocation::Vertex) {
    int k = 0;
    while (std::abs(corner[k][0] - n.uv[0]) + std::abs(corner[k][1] - n.uv[1]) > 1e-12)
      ++k;
    const int64_t v = topo.cell_vertices(n.cell)[k];
    for (int64_t c = 0; c < topo.num_cells(); ++c)
      for (int j = 0; j < 3; ++j)
        if (topo.cell_vertices(c)[j] == v)
          where.push_back({c, corner[j]});
  } else {
    // The edge of n.cell the node lies on, and the same point in the neighbour.
    const double u = n.uv[0], v = n.uv[1];
    const int k = std::abs(v) < 1e-12 ? 0 : (std::abs(u + v - 1) < 1e-12 ? 1 : 2);
    const double s = k == 0 ? u : (k == 1 ? v : 1 - v);
    where.push_back({n.cell, {u, v}});
    const int64_t e = topo.cell_edge(n.cell, k);
    const double t = topo.edge_reversed(n.cell, k) ? 1 - s : s;
    for (int i = 0; i < topo.edge_cell_count(e); ++i) {
      const int64_t c = topo.edge_cells_begin(e)[i];
      if (c == n.cell)
        continue;
      int kk = 0;
      while (topo.cell_edge(c, kk) != e)
        ++kk;
      const double sc = topo.edge_reversed(c, kk) ? 1 - t : t;
      const Vec2 &a = corner[kk], &b = corner[(kk + 1) % 3];
      where.push_back({c, {a[0] + sc * (b[0] - a[0]), a[1] + sc * (b[1] - a[1])}});
    }
  }
  int checked = 0;
  for (const auto &[c, p] : where)
    for (double r : {1e-3, 1e-4})
      for (int i = 0; i < 64; ++i) {
        const double a = 2 * M_PI * i / 64;
        const double u = p[0] + r * std::cos(a), v = p[1] + r * std::sin(a);
        if (u < 0 || v < 0 || u + v > 1)
          continue;
        const double val = m.field.value(c, u, v);
        ++checked;
        if (n.type == NodeType::Minimum) {
          EXPECT_GE(val, n.value - 1e-12) << "minimum in cell " << c;
        } else {
          EXPECT_LE(val, n.value + 1e-12) << "maximum in cell " << c;
        }
      }
  EXPECT_GT(checked, 0);
}

// Invariants every tree must satisfy.
void check_invariants(const TreeResult &t, const Mesh &m) {
  ASSERT_EQ(t.arcs.size() + 1, t.nodes.size());
  int64_t sum = 0;
  for (const auto &n : t.nodes) {
    sum += n.up + n.down - 2;
    EXPECT_NE(n.up + n.down, 0);
    // Values equal the field at the node's position.
    EXPECT_NEAR(n.value, m.field.value(n.cell, n.uv[0], n.uv[1]),
                1e-10 * std::max(1.0, std::abs(n.value)));
    if (!t.augmented) {
      EXPECT_NE(n.type, NodeType::Regular);
    }
    // Leaves are local extrema (the fallback's PL leaves are extrema of the refinement only).
    if (n.up + n.down == 1 && !n.fallback && m.topology.num_cells() <= 5000)
      check_leaf_is_extremum(n, m);
  }
  EXPECT_EQ(sum, -2);
}

std::vector<std::array<double, 2>> diagram(const TreeResult &t, PersistencePair::Kind kind,
                                           double min_persistence = 0) {
  std::vector<std::array<double, 2>> p;
  for (const auto &x : t.pairs)
    if (x.kind == kind && x.persistence() > min_persistence)
      p.push_back({x.birth_value, x.death_value});
  return p;
}

TEST(ExactTree, FieldOnTheSphereMatchesTheAnalyticTopologyAndTheFinePlTree) {
  // g = x'y'z' (rotated frame) sampled at the nodes of curved cells: 4 maxima, 4 minima and
  // 6 saddles of high persistence, near the analytic ones. The interpolated field may add tiny
  // features near cell edges (it is only C0 there): those are real extrema of the
  // piecewise-polynomial field, below the resolution of a PL refinement.
  const Rotation rot;
  std::mt19937_64 rng(3);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::octahedron(4, v, t);
  const double s3 = 1 / std::sqrt(3.0);
  for (int degree : {2, 3, 4, 6, 8}) {
    const MeshInput in = testing::lagrange_mesh(
        v, t, [&](int64_t) { return degree; }, testing::sphere_projection,
        [&](const Vec3 &p) {
          const Vec3 q = rot.apply(p);
          return q[0] * q[1] * q[2];
        },
        rng);
    const Mesh mesh = build_mesh(in);
    const TreeResult tree = exact_contour_tree(mesh);
    check_invariants(tree, mesh);
    EXPECT_EQ(stat(tree, "fallback_cells"), 0) << "degree " << degree;
    EXPECT_EQ(diagram(tree, PersistencePair::Kind::Join, 0.01).size(), 3u) << degree;
    EXPECT_EQ(diagram(tree, PersistencePair::Kind::Split, 0.01).size(), 3u) << degree;
    // The high-persistence extrema sit near the analytic ones (interpolation error: quadratics
    // on this coarse mesh are off by a few percent).
    const double tol = degree == 2 ? 0.06 : 0.02;
    for (const auto &n : tree.nodes) {
      if (n.type != NodeType::Maximum || n.value < 0.15)
        continue;
      const Vec3 q = rot.apply(n.position);
      EXPECT_NEAR(std::abs(q[0]), s3, tol) << "degree " << degree;
      EXPECT_NEAR(std::abs(q[1]), s3, tol) << "degree " << degree;
      EXPECT_GT(q[0] * q[1] * q[2], 0);
    }
    // Against the PL tree of a fine refinement: the diagrams agree to the PL resolution.
    const TreeResult pl = pl_contour_tree(refine(mesh, 16), false, "");
    for (auto kind :
         {PersistencePair::Kind::Join, PersistencePair::Kind::Split, PersistencePair::Kind::Global})
      EXPECT_LT(bottleneck_distance(diagram(tree, kind), diagram(pl, kind)), 2e-3)
          << "degree " << degree << " " << to_string(kind);
  }
}

TEST(ExactTree, GlobalPolynomialOnStraightCellsHasExactlyItsCriticalPoints) {
  // f = A(x) + B(y) on the unit square, represented exactly by straight cells of degree >= 4:
  // interior critical points exactly at (r_i, s_j), minima where A'' > 0 and B'' > 0, maxima
  // where both < 0, saddles otherwise. Every one is a node of the tree, within 1e-8.
  const std::vector<double> r = {0.23, 0.61, 0.83}, s = {0.17, 0.52, 0.79};
  const auto A = antiderivative_of_roots(r, 1.0), B = antiderivative_of_roots(s, -1.3);
  auto f = [&](const Vec3 &p) { return horner(A, p[0]) + horner(B, p[1]); };
  auto second = [](const std::vector<double> &a, double x) {
    double sum = 0;
    for (std::size_t i = 2; i < a.size(); ++i)
      sum += a[i] * static_cast<double>(i * (i - 1)) * std::pow(x, static_cast<double>(i - 2));
    return sum;
  };
  for (int degree : {4, 5, 8}) {
    std::mt19937_64 rng(7 + degree);
    std::vector<Vec3> v;
    std::vector<std::array<int64_t, 3>> t;
    testing::square_grid(5, rng, v, t);
    const Mesh mesh = build_mesh(testing::lagrange_mesh(
        v, t, [&](int64_t) { return degree; }, nullptr, f, rng));
    const TreeResult tree = exact_contour_tree(mesh);
    check_invariants(tree, mesh);
    int found = 0;
    for (double x : r)
      for (double y : s) {
        const double ax = second(A, x), by = second(B, y);
        const NodeType want = ax > 0 && by > 0   ? NodeType::Minimum
                              : ax < 0 && by < 0 ? NodeType::Maximum
                                                 : NodeType::Saddle;
        bool hit = false;
        for (const auto &n : tree.nodes)
          if (std::abs(n.position[0] - x) < 1e-8 && std::abs(n.position[1] - y) < 1e-8) {
            hit = true;
            EXPECT_EQ(n.type, want) << "(" << x << ", " << y << ") degree " << degree;
          }
        EXPECT_TRUE(hit) << "missing (" << x << ", " << y << ") degree " << degree;
        found += hit;
      }
    EXPECT_EQ(found, 9);
  }
}

TEST(ExactTree, RandomFieldsAgreeWithFinePlRefinements) {
  for (bool sphere : {false, true})
    for (int degree : {2, 3, 5}) {
      std::mt19937_64 rng(31 + degree + (sphere ? 100 : 0));
      std::uniform_real_distribution<double> U(-1, 1);
      std::vector<std::array<double, 4>> modes;
      for (int i = 0; i < 6; ++i)
        modes.push_back({4 * U(rng), 4 * U(rng), 4 * U(rng), U(rng)});
      auto f = [&](const Vec3 &p) {
        double sum = 0;
        for (const auto &m : modes)
          sum += m[3] * std::cos(m[0] * p[0] + m[1] * p[1] + m[2] * p[2]);
        return sum;
      };
      std::vector<Vec3> v;
      std::vector<std::array<int64_t, 3>> t;
      if (sphere)
        testing::octahedron(3, v, t);
      else
        testing::square_grid(4, rng, v, t);
      const Mesh mesh = build_mesh(testing::lagrange_mesh(
          v, t, [&](int64_t) { return degree; }, sphere ? testing::sphere_projection : nullptr, f,
          rng));
      const TreeResult tree = exact_contour_tree(mesh);
      check_invariants(tree, mesh);
      for (auto kind : {PersistencePair::Kind::Join, PersistencePair::Kind::Split,
                        PersistencePair::Kind::Global}) {
        double last = INFINITY;
        for (int k : {4, 16, 64}) {
          const double d = bottleneck_distance(
              diagram(tree, kind), diagram(pl_contour_tree(refine(mesh, k), false, ""), kind));
          EXPECT_LE(d, last * 1.0001 + 1e-12) << to_string(kind) << " k=" << k;
          last = d;
        }
        EXPECT_LT(last, 1e-3) << to_string(kind) << " degree " << degree << " sphere " << sphere;
      }
    }
}

TEST(ExactTree, DegenerateDataGivesAValidTreeAndCountsFallbacks) {
  std::mt19937_64 rng(77);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(6, rng, v, t);
  // A ridge: the maximum is the whole segment y = 0.47 (exactly quadratic, so the ridge cells
  // have a curve of critical points), the sides y = 0 and y = 1 constant edges (level edges).
  // Both are certified: no fallback.
  {
    const Mesh mesh = build_mesh(testing::lagrange_mesh(
        v, t, [](int64_t) { return 2; }, nullptr,
        [](const Vec3 &p) { return -(p[1] - 0.47) * (p[1] - 0.47); }, rng));
    const TreeResult tree = exact_contour_tree(mesh);
    check_invariants(tree, mesh);
    EXPECT_EQ(stat(tree, "fallback_cells"), 0);
    EXPECT_GT(stat(tree, "critical_curves"), 0);
    EXPECT_EQ(stat(tree, "level_edges"), 12); // the bottom and top sides' six edges each
    // (Flat regions not contracted here: the sides' vertices are nodes, all of the side's value.)
    for (const TreeNode &n : tree.nodes) {
      const bool top = std::abs(n.value + 0.53 * 0.53) < 1e-12;
      const bool bottom = std::abs(n.value + 0.47 * 0.47) < 1e-12;
      const bool ridge = std::abs(n.value) < 1e-12;
      EXPECT_TRUE(top || bottom || ridge) << n.value;
      EXPECT_EQ(n.type == NodeType::Maximum, ridge && n.type != NodeType::Saddle) << n.value;
    }
  }
  // A plateau: constant where x < 0.4, a bowl elsewhere; constant cells fall back.
  {
    const Mesh mesh = build_mesh(testing::lagrange_mesh(
        v, t, [](int64_t) { return 3; }, nullptr,
        [](const Vec3 &p) { return p[0] < 0.4 ? 0.0 : std::sin(9 * (p[0] - 0.4)) * p[1]; }, rng));
    const TreeResult tree = exact_contour_tree(mesh);
    check_invariants(tree, mesh);
    EXPECT_GT(stat(tree, "fallback_constant_cell"), 0);
  }
  // Equal vertex values everywhere on a coarse level set: values rounded to 0.25 steps.
  {
    const Mesh mesh = build_mesh(testing::lagrange_mesh(
        v, t, [](int64_t) { return 2; }, nullptr,
        [](const Vec3 &p) { return std::round(4 * std::sin(5 * p[0]) * std::cos(4 * p[1])) / 4; },
        rng));
    const TreeResult tree = exact_contour_tree(mesh);
    check_invariants(tree, mesh);
  }
}

} // namespace
} // namespace hoct

#include "datasets/datasets.hpp"

namespace hoct {
namespace {

TEST(ExactTree, LinearCellsGiveExactlyThePlTree) {
  // Degree 1: the field is piecewise linear, so the exact tree must be the PL tree of the mesh:
  // the same diagram, and critical points only at vertices.
  for (bool sphere : {false, true}) {
    std::mt19937_64 rng(sphere ? 5 : 6);
    std::vector<Vec3> v;
    std::vector<std::array<int64_t, 3>> t;
    if (sphere)
      testing::octahedron(5, v, t);
    else
      testing::square_grid(9, rng, v, t);
    const MeshInput in = testing::lagrange_mesh(
        v, t, [](int64_t) { return 1; }, sphere ? testing::sphere_projection : nullptr, nullptr,
        rng);
    const Mesh mesh = build_mesh(in);
    const TreeResult exact = exact_contour_tree(mesh);
    const TreeResult pl = pl_contour_tree(split_lagrange_cells(in), false, "");
    check_invariants(exact, mesh);
    ASSERT_EQ(exact.nodes.size(), pl.nodes.size());
    for (const auto &n : exact.nodes)
      EXPECT_EQ(n.location, NodeLocation::Vertex);
    for (auto kind :
         {PersistencePair::Kind::Join, PersistencePair::Kind::Split, PersistencePair::Kind::Global})
      EXPECT_EQ(bottleneck_distance(diagram(exact, kind), diagram(pl, kind)), 0.0);
  }
}

TEST(ExactTree, IdenticalForAnyThreadCount) {
  std::vector<std::pair<std::string, Mesh>> meshes;
  for (const std::string name : {"conductor", "random", "sphere"}) {
    DatasetOptions o;
    o.cells = 3000;
    meshes.emplace_back(name, build_mesh(generate_dataset(name, o)));
  }
  {
    // A plateau: constant where x < 0.4, so that fallback cells (refined in the graph assembly,
    // after the threads' chunks are combined) lie in many chunks.
    std::mt19937_64 rng(78);
    std::vector<Vec3> v;
    std::vector<std::array<int64_t, 3>> t;
    testing::square_grid(30, rng, v, t);
    meshes.emplace_back(
        "plateau",
        build_mesh(testing::lagrange_mesh(
            v, t, [](int64_t) { return 3; }, nullptr,
            [](const Vec3 &p) { return p[0] < 0.4 ? 0.0 : std::sin(9 * (p[0] - 0.4)) * p[1]; },
            rng)));
  }
  for (const auto &[name, mesh] : meshes) {
    ExactTreeOptions one, two, many;
    one.threads = 1;
    two.threads = 2;
    many.threads = 7;
    two.cells_per_thread = many.cells_per_thread = 1; // really use the threads on 3000 cells
    const TreeResult a = exact_contour_tree(mesh, one), b = exact_contour_tree(mesh, two),
                     c = exact_contour_tree(mesh, many);
    if (name == "plateau") {
      ASSERT_GT(stat(a, "fallback_cells"), 100);
    }
    for (const TreeResult *t : {&b, &c}) {
      ASSERT_EQ(t->nodes.size(), a.nodes.size()) << name;
      for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_EQ(std::memcmp(&t->nodes[i].value, &a.nodes[i].value, sizeof(double)), 0);
        EXPECT_EQ(t->nodes[i].uv, a.nodes[i].uv);
        EXPECT_EQ(t->nodes[i].cell, a.nodes[i].cell);
        EXPECT_EQ(t->nodes[i].type, a.nodes[i].type);
      }
      EXPECT_EQ(t->arcs, a.arcs) << name;
      for (const auto &[k, v] : a.stats.entries()) {
        if (k.rfind("time_", 0) != 0) {
          EXPECT_EQ(stat(*t, k), v) << name << " " << k;
        }
      }
    }
    // With the arcs' geometry (the edge chains' pieces placed on the threads, the fallback
    // cells' lattice nodes among them): the same arcs drawn through the same points.
    std::vector<std::vector<std::vector<Vec3>>> paths;
    for (ExactTreeOptions o : {one, two, many}) {
      o.arc_geometry = true;
      TreeResult t = exact_contour_tree(mesh, o);
      EXPECT_EQ(t.arcs, a.arcs) << name;
      compute_arc_paths(t, o.threads); // the arcs' searches on the threads too
      paths.push_back(t.arc_paths);
    }
    ASSERT_EQ(paths[0].size(), a.arcs.size()) << name;
    for (std::size_t i = 0; i < paths[0].size(); ++i) {
      ASSERT_EQ(paths[1][i].size(), paths[0][i].size()) << name << " arc " << i;
      ASSERT_EQ(paths[2][i].size(), paths[0][i].size()) << name << " arc " << i;
      EXPECT_EQ(std::memcmp(paths[1][i].data(), paths[0][i].data(), paths[0][i].size() * 24), 0);
      EXPECT_EQ(std::memcmp(paths[2][i].data(), paths[0][i].data(), paths[0][i].size() * 24), 0);
    }
  }
}

// The cell phase's time is split between its two passes, interior critical points and
// connections, on any thread count: both are set, and they add up to the phase.
TEST(ExactTree, CellPhaseTimeSplitsIntoCriticalPointsAndConnections) {
  DatasetOptions o;
  o.cells = 3000;
  const Mesh mesh = build_mesh(generate_dataset("random", o));
  for (int threads : {1, 2}) {
    ExactTreeOptions eo;
    eo.threads = threads;
    eo.cells_per_thread = 1;
    const TreeResult t = exact_contour_tree(mesh, eo);
    ASSERT_GT(stat(t, "interior_critical_points"), 0);
    ASSERT_GT(stat(t, "connections_direct") + stat(t, "connections_traced"), 0);
    const double cells = stat(t, "time_cells_s"),
                 critical = stat(t, "time_interior_critical_points_s"),
                 connections = stat(t, "time_connections_s");
    EXPECT_GT(critical, 0) << threads;
    EXPECT_GT(connections, 0) << threads;
    EXPECT_NEAR(critical + connections, cells, 1e-12 * cells) << threads;
  }
}

TEST(ExactTree, GeneratedDatasetsAgreeWithFinePlRefinements) {
  // For every dataset: the bottleneck distance between the exact diagram and the diagram of the
  // PL tree of the k-refinement shrinks as k grows and ends small against the value range.
  const std::vector<std::pair<std::string, long long>> sets = {
      {"gauss", 0},     {"sphere", 0},      {"two-triangle", 0},
      {"heater", 1500}, {"conductor", 700}, {"random", 2000}};
  for (const auto &[name, cells] : sets) {
    DatasetOptions o;
    o.cells = cells;
    const Mesh mesh = build_mesh(generate_dataset(name, o));
    const TreeResult tree = exact_contour_tree(mesh);
    check_invariants(tree, mesh);
    const double range = mesh.field.max_value() - mesh.field.min_value();
    std::vector<double> dist;
    for (int k : {2, 8, 32}) {
      const TreeResult pl = pl_contour_tree(refine(mesh, k), false, "");
      double d = 0;
      for (auto kind : {PersistencePair::Kind::Join, PersistencePair::Kind::Split,
                        PersistencePair::Kind::Global})
        d = std::max(d, bottleneck_distance(diagram(tree, kind), diagram(pl, kind)));
      dist.push_back(d / range);
    }
    EXPECT_LE(dist[2], dist[0]) << name;
    EXPECT_LT(dist[2], 2e-3) << name << ": " << dist[0] << " " << dist[1] << " " << dist[2];
  }
}

} // namespace
} // namespace hoct
