// The generated datasets: sizes, determinism, shared edge nodes, the degeneracies the
// conductor must contain, and the two-triangle toy's critical points.
#include "datasets/datasets.hpp"
#include "error.hpp"
#include "mesh/mesh.hpp"
#include "poly/lattice.hpp"
#include "tree/exact_contour_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace hoct {
namespace {

MeshInput make(const std::string &name, long long cells = 0, int degree = 0, uint64_t seed = 1) {
  DatasetOptions o;
  o.cells = cells;
  o.degree = degree;
  o.seed = seed;
  return generate_dataset(name, o);
}

TEST(Datasets, SizesDegreesAndValidity) {
  const std::map<std::string, std::pair<long long, int>> defaults = {
      {"gauss", {722, 2}},      {"sphere", {1056, 3}}, {"two-triangle", {2, 5}},
      {"heater", {12438, 3}},   {"conductor", {4298, 2}}, {"random", {20000, 3}}};
  for (const auto &name : dataset_names()) {
    const MeshInput m = make(name);
    const auto [target, degree] = defaults.at(name);
    EXPECT_NEAR(static_cast<double>(m.num_cells()), static_cast<double>(target), 0.1 * target)
        << name;
    for (uint8_t d : m.cell_degree)
      ASSERT_EQ(d, degree) << name;
    const Mesh mesh = build_mesh(m, {.throw_on_error = false});
    EXPECT_FALSE(mesh.problems.has_errors()) << name << "\n" << mesh.problems.summary();
  }
  EXPECT_THROW(make("nope"), Error);
  EXPECT_THROW(make("random", 0, 42), Error);
  EXPECT_THROW(make("two-triangle", 10), Error);
  EXPECT_EQ(make("random", 1000, 6).cell_degree[0], 6);
  EXPECT_NEAR(static_cast<double>(make("random", 200000, 1).num_cells()), 200000, 2000);
}

TEST(Datasets, DeterministicForASeed) {
  for (const auto &name : dataset_names()) {
    const MeshInput a = make(name, name == "heater" ? 800 : 0), b = make(name, name == "heater" ? 800 : 0);
    const MeshInput c = make(name, name == "heater" ? 800 : 0, 0, 2);
    EXPECT_EQ(a.values, b.values) << name;
    EXPECT_EQ(a.cell_nodes, b.cell_nodes) << name;
    EXPECT_NE(a.values, c.values) << name;
  }
}

TEST(Datasets, EdgesShareTheirNodesAndSurfacesAreExact) {
  for (const auto &name : {"sphere", "conductor", "gauss"}) {
    const MeshInput m = make(name, std::string(name) == "conductor" ? 600 : 0);
    // For every pair of cells sharing two corners, the edge's interior node ids agree.
    std::map<std::pair<int64_t, int64_t>, std::vector<int64_t>> seen;
    int64_t shared = 0;
    for (std::size_t c = 0; c < m.num_cells(); ++c) {
      const int d = m.cell_degree[c];
      const int64_t *n = &m.cell_nodes[m.cell_offsets[c]];
      for (int k = 0; k < 3; ++k) {
        std::vector<int64_t> ids;
        for (int t = 0; t <= d; ++t)
          ids.push_back(n[edge_lattice_index(d, k, t)]);
        if (ids.front() > ids.back())
          std::reverse(ids.begin(), ids.end());
        auto [it, fresh] = seen.try_emplace({ids.front(), ids.back()}, ids);
        if (!fresh) {
          EXPECT_EQ(it->second, ids) << name << " cell " << c;
          ++shared;
        }
      }
    }
    EXPECT_GT(shared, 0) << name;
  }
  const MeshInput s = make("sphere");
  for (const auto &p : s.points)
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-12);
}

TEST(Datasets, ConductorHasPlateausAndRidges) {
  const MeshInput m = make("conductor");
  const Mesh mesh = build_mesh(m);
  int64_t constant = 0, ridge = 0;
  for (int64_t c = 0; c < mesh.topology.num_cells(); ++c) {
    const BernsteinTriangle g = mesh.field.cell_polynomial(c);
    auto [lo, hi] = g.bounds();
    if (hi - lo <= 1e-12)
      ++constant;
    // An exact ridge cell: the gradient vanishes at two distinct points of the cell.
    const Vec3 p0 = mesh.geometry.position(c, 0, 0), p1 = mesh.geometry.position(c, 1, 0),
               p2 = mesh.geometry.position(c, 0, 1);
    const double cx = p0[0] < 1.5 ? 0.5 : 2.5;
    const double xmin = std::min({p0[0], p1[0], p2[0]}), xmax = std::max({p0[0], p1[0], p2[0]});
    const double ymax = std::max({p0[1], p1[1], p2[1]});
    if (xmin < cx && cx < xmax && ymax < 1.2)
      ++ridge;
  }
  EXPECT_GT(constant, 10);
  EXPECT_GT(ridge, 10);
  const TreeResult t = exact_contour_tree(mesh);
  double fallbacks = 0;
  for (const auto &[k, v] : t.stats)
    if (k == "fallback_cells")
      fallbacks = v;
  EXPECT_GT(fallbacks, 0);
  EXPECT_EQ(t.arcs.size() + 1, t.nodes.size());
}

TEST(Datasets, TwoTriangleHasItsSixteenInteriorCriticalPoints) {
  // f = A(x) + s B(y) with A' roots .35 .60 .75 .92 and B' roots .10 .30 .65 .85 (see
  // two_triangle.cpp): 11 critical points below the diagonal, 5 above.
  const double rx[4] = {0.35, 0.60, 0.75, 0.92}, ry[4] = {0.10, 0.30, 0.65, 0.85};
  const Mesh mesh = build_mesh(make("two-triangle"));
  const TreeResult t = exact_contour_tree(mesh);
  int below = 0, above = 0;
  for (double x : rx)
    for (double y : ry) {
      bool hit = false;
      for (const auto &n : t.nodes)
        if (n.location == NodeLocation::Interior && std::abs(n.position[0] - x) < 1e-8 &&
            std::abs(n.position[1] - y) < 1e-8) {
          hit = true;
          EXPECT_EQ(n.cell, y < x ? 0 : 1);
        }
      EXPECT_TRUE(hit) << "(" << x << ", " << y << ")";
      (y < x ? below : above) += hit;
    }
  EXPECT_EQ(below, 11);
  EXPECT_EQ(above, 5);
}

} // namespace
} // namespace hoct
