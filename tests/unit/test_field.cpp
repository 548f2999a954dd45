// The field: interpolation of the node values, and bit-identical edge restrictions on both sides
// of every edge, on random meshes of degree 1..8 (uniform and mixed).
#include "mesh/mesh.hpp"
#include "poly/lattice.hpp"
#include "test_meshes.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace hoct {
namespace {

// Every cell's restriction to each of its edges, read off its own coefficients and oriented
// lo -> hi, must be bit-for-bit the edge's polynomial (degree-elevated to the cell's degree).
void expect_bit_identical_edges(const Mesh &m) {
  const auto &topo = m.topology;
  int64_t checked = 0;
  for (int64_t c = 0; c < topo.num_cells(); ++c) {
    const BernsteinTriangle poly = m.field.cell_polynomial(c);
    for (int k = 0; k < 3; ++k) {
      const int64_t e = topo.cell_edge(c, k);
      BernsteinPoly mine = poly.edge(k);
      if (topo.edge_reversed(c, k))
        mine = mine.reversed();
      BernsteinPoly shared = m.field.edge_polynomial(e);
      if (shared.degree() != mine.degree())
        shared = shared.elevated(mine.degree());
      ASSERT_EQ(mine.coefficients().size(), shared.coefficients().size());
      ASSERT_EQ(0, std::memcmp(mine.coefficients().data(), shared.coefficients().data(),
                               sizeof(double) * shared.coefficients().size()))
          << "cell " << c << " edge " << k;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3 * topo.num_cells());
}

class FieldDegree : public ::testing::TestWithParam<int> {};

TEST_P(FieldDegree, SharedEdgesAreBitIdenticalAndNodesInterpolated) {
  const int d = GetParam();
  std::mt19937_64 rng(2024 + d);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(6, rng, verts, tris);
  const MeshInput in = testing::lagrange_mesh(
      verts, tris, [&](int64_t) { return d; }, nullptr, nullptr, rng);
  const Mesh m = build_mesh(in);
  EXPECT_EQ(m.topology.euler_characteristic(), 1);
  expect_bit_identical_edges(m);
  // The cell polynomial interpolates its (random) node values.
  for (int64_t c = 0; c < m.topology.num_cells(); ++c) {
    const BernsteinTriangle poly = m.field.cell_polynomial(c);
    for (int i = 0; i < lattice_size(d); ++i) {
      const auto q = lattice_point(d, i);
      const double val = in.values[in.cell_nodes[in.cell_offsets[c] + i]];
      EXPECT_NEAR(poly(static_cast<double>(q[0]) / d, static_cast<double>(q[1]) / d), val, 1e-11);
    }
  }
}

TEST_P(FieldDegree, SphereEdgesAreBitIdentical) {
  const int d = GetParam();
  std::mt19937_64 rng(77 + d);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::octahedron(3, verts, tris);
  const MeshInput in = testing::lagrange_mesh(
      verts, tris, [&](int64_t) { return d; }, testing::sphere_projection,
      [](const Vec3 &p) { return p[0] * p[1] + std::sin(3 * p[2]); }, rng);
  const Mesh m = build_mesh(in);
  EXPECT_EQ(m.topology.euler_characteristic(), 2);
  EXPECT_EQ(m.topology.boundary_loops(), 0);
  EXPECT_FALSE(m.geometry.planar());
  EXPECT_EQ(m.geometry.curved_cells(), d >= 2 ? m.topology.num_cells() : 0);
  expect_bit_identical_edges(m);
}

INSTANTIATE_TEST_SUITE_P(Degrees1To8, FieldDegree, ::testing::Range(1, 9));

TEST(Field, MixedDegreesElevateAndStayContinuous) {
  // A field that is one global quadratic, sampled on cells of degree 2..5: all edges agree.
  std::mt19937_64 rng(5);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(5, rng, verts, tris);
  auto f = [](const Vec3 &p) { return 1 + p[0] - 2 * p[1] + 3 * p[0] * p[1] - p[0] * p[0]; };
  const MeshInput in = testing::lagrange_mesh(
      verts, tris, [](int64_t c) { return 2 + static_cast<int>(c % 4); }, nullptr, f, rng);
  const Mesh m = build_mesh(in);
  EXPECT_FALSE(m.problems.has_errors()) << m.problems.summary();
  expect_bit_identical_edges(m);
  for (int64_t c = 0; c < m.topology.num_cells(); ++c) {
    EXPECT_GE(m.field.degree(c), in.cell_degree[c]);
    const Vec3 p = m.geometry.position(c, 0.2, 0.3);
    EXPECT_NEAR(m.field.value(c, 0.2, 0.3), f(p), 1e-12);
  }
}

TEST(Field, DiscontinuityAcrossAnEdgeIsReported) {
  // Two cells of different degree whose shared edge disagrees: random node values.
  std::mt19937_64 rng(6);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(2, rng, verts, tris);
  const MeshInput in = testing::lagrange_mesh(
      verts, tris, [](int64_t c) { return c == 0 ? 2 : 3; }, nullptr, nullptr, rng);
  ProblemLog log;
  const Mesh m = build_mesh(in, {.throw_on_error = false});
  EXPECT_GT(m.problems.count(Problem::DiscontinuousEdge), 0);
  EXPECT_THROW(build_mesh(in), Error);
}

TEST(Field, DuplicatedEdgeNodesWithEqualValuesAreAccepted) {
  // Two triangles whose shared edge nodes are separate points with equal positions and values.
  MeshInput in;
  auto pt = [&](double x, double y) {
    in.points.push_back({x, y, 0});
    in.values.push_back(x * x + y);
    return static_cast<int64_t>(in.points.size() - 1);
  };
  const int64_t a = pt(0, 0), b = pt(1, 0), c = pt(1, 1), d = pt(0, 1);
  const int64_t ac1 = pt(0.5, 0.5), ac2 = pt(0.5, 0.5);
  // Cell 0: a b c (ccw) with edge nodes ab, bc, ca; cell 1: a c d.
  const int64_t ab = pt(0.5, 0), bc = pt(1, 0.5), cd = pt(0.5, 1), da = pt(0, 0.5);
  // canonical order for d = 2: (0,0) (1,0) (2,0) (0,1) (1,1) (0,2)
  const int64_t c0[6] = {a, ab, b, ac1, bc, c};
  const int64_t c1[6] = {a, ac2, c, da, cd, d};
  in.add_cell(2, c0);
  in.add_cell(2, c1);
  const Mesh m = build_mesh(in);
  EXPECT_FALSE(m.problems.has_errors());
  in.values[ac2] += 0.5;
  EXPECT_THROW(build_mesh(in), Error);
}

} // namespace
} // namespace hoct

namespace hoct {
namespace {

TEST(FieldFromSamples, ArbitrarySamplesGiveAContinuousExactField) {
  // A global cubic sampled at random (well-spread) parametric points in every cell of a
  // straight-sided mesh: the fitted field reproduces it and the edges are shared bit-for-bit.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(4, rng, verts, tris);
  auto f = [](double x, double y) { return x * x * x - 2 * x * y * y + 0.5 * y - x * y + 3; };
  const MeshInput in = testing::lagrange_mesh(
      verts, tris, [](int64_t) { return 1; }, nullptr, nullptr, rng);
  std::vector<CellSamples> samples(in.num_cells());
  for (std::size_t c = 0; c < in.num_cells(); ++c) {
    samples[c].degree = 3;
    const Vec3 &p0 = in.points[in.cell_nodes[in.cell_offsets[c]]];
    const Vec3 &p1 = in.points[in.cell_nodes[in.cell_offsets[c] + 1]];
    const Vec3 &p2 = in.points[in.cell_nodes[in.cell_offsets[c] + 2]];
    for (int i = 0; i < 12; ++i) { // more samples than the 10 coefficients: least squares
      double u = U(rng), v = U(rng);
      if (u + v > 1) {
        u = 1 - u;
        v = 1 - v;
      }
      const double x = (1 - u - v) * p0[0] + u * p1[0] + v * p2[0];
      const double y = (1 - u - v) * p0[1] + u * p1[1] + v * p2[1];
      samples[c].positions.push_back({u, v});
      samples[c].values.push_back(f(x, y));
    }
  }
  const Mesh m = build_mesh_from_samples(in, samples);
  expect_bit_identical_edges(m);
  for (int64_t c = 0; c < m.topology.num_cells(); ++c) {
    const Vec3 p = m.geometry.position(c, 0.3, 0.3);
    EXPECT_NEAR(m.field.value(c, 0.3, 0.3), f(p[0], p[1]), 1e-9);
  }
  // One cell sampled from another function: a discontinuity, reported with its cell.
  auto bad = samples;
  for (auto &v : bad[5].values)
    v += 0.1;
  const Mesh b = build_mesh_from_samples(in, bad, {false});
  EXPECT_GT(b.problems.count(Problem::DiscontinuousEdge), 0);
  // A degenerate sample set: all samples of cell 3 on one line.
  auto line = samples;
  for (auto &p : line[3].positions)
    p = {p[0], 0.0};
  const Mesh l = build_mesh_from_samples(in, line, {false});
  ASSERT_EQ(l.problems.count(Problem::BadSampleSet), 1);
  EXPECT_NE(l.problems.kinds().at(Problem::BadSampleSet).examples[0].find("cell 3"),
            std::string::npos);
}

} // namespace
} // namespace hoct

namespace hoct {
namespace {

TEST(Geometry, SameMapsOnAnyThreadCount) {
  // Degrees 1 to 4, straight cells below the equator and curved ones above: the maps built on
  // one and on three threads agree bit for bit (16,200 cells: enough for three threads).
  std::mt19937_64 rng(9);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::octahedron(45, v, t);
  const MeshInput in = testing::lagrange_mesh(
      v, t, [](int64_t c) { return 1 + static_cast<int>(c % 4); },
      [](const Vec3 &p) { return p[2] > 0 ? testing::sphere_projection(p) : p; }, nullptr, rng);
  const Geometry one = Geometry::build(in, 1), three = Geometry::build(in, 3);
  ASSERT_EQ(one.num_cells(), three.num_cells());
  EXPECT_EQ(one.curved_cells(), three.curved_cells());
  EXPECT_GT(one.curved_cells(), 0);
  EXPECT_LT(one.curved_cells(), one.num_cells() * 3 / 4); // degree-1 and lower cells straight
  for (int64_t c = 0; c < one.num_cells(); ++c) {
    ASSERT_EQ(one.degree(c), three.degree(c)) << c;
    for (const auto &[u, w] : {std::pair{0.2, 0.3}, std::pair{0.0, 1.0}, std::pair{0.6, 0.1}}) {
      const Vec3 a = one.position(c, u, w), b = three.position(c, u, w);
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << c;
    }
  }
}

TEST(Geometry, PositionAndJacobianOfCurvedCells) {
  // Curved cubic cells on the sphere: positions interpolate the nodes, the Jacobian matches
  // central differences of the position.
  std::mt19937_64 rng(4);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::octahedron(2, v, t);
  const MeshInput in = testing::lagrange_mesh(
      v, t, [](int64_t) { return 3; }, testing::sphere_projection, nullptr, rng);
  const Mesh m = build_mesh(in);
  for (int64_t c = 0; c < m.topology.num_cells(); ++c) {
    for (int i = 0; i < lattice_size(3); ++i) {
      const auto q = lattice_point(3, i);
      const Vec3 p = m.geometry.position(c, q[0] / 3.0, q[1] / 3.0);
      const Vec3 &node = in.points[in.cell_nodes[in.cell_offsets[c] + i]];
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(p[a], node[a], 1e-12);
    }
    const double u = 0.3, w = 0.2, h = 1e-6;
    const auto j = m.geometry.jacobian(c, u, w);
    const Vec3 pu1 = m.geometry.position(c, u + h, w), pu0 = m.geometry.position(c, u - h, w);
    const Vec3 pv1 = m.geometry.position(c, u, w + h), pv0 = m.geometry.position(c, u, w - h);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(j[0][a], (pu1[a] - pu0[a]) / (2 * h), 1e-7);
      EXPECT_NEAR(j[1][a], (pv1[a] - pv0[a]) / (2 * h), 1e-7);
    }
  }
}

} // namespace
} // namespace hoct
