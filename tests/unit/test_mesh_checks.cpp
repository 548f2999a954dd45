// Topology invariants and the problems the mesh checks must find.
#include "mesh/duplicate_points.hpp"
#include "mesh/mesh.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"
#include "test_meshes.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <functional>
#include <limits>
#include <numeric>
#include <random>

namespace hoct {
namespace {

MeshInput linear_mesh(const std::vector<Vec3> &v, const std::vector<std::array<int64_t, 3>> &t) {
  MeshInput m;
  m.points.assign(v.begin(), v.end());
  m.values.assign(v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    m.values[i] = v[i][0] + 2 * v[i][1];
  for (const auto &tri : t)
    m.add_cell(1, tri.data());
  m.source = "test";
  return m;
}

bool message_contains(const Mesh &m, Problem kind, const std::string &text) {
  auto it = m.problems.kinds().find(kind);
  if (it == m.problems.kinds().end())
    return false;
  for (const auto &e : it->second.examples)
    if (e.find(text) != std::string::npos)
      return true;
  return false;
}

TEST(Topology, DiskSphereAndAnnulus) {
  std::mt19937_64 rng(1);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(4, rng, v, t);
  Mesh disk = build_mesh(linear_mesh(v, t));
  EXPECT_EQ(disk.topology.num_vertices(), 25);
  EXPECT_EQ(disk.topology.num_edges(), 56);
  EXPECT_EQ(disk.topology.num_cells(), 32);
  EXPECT_EQ(disk.topology.euler_characteristic(), 1);
  EXPECT_EQ(disk.topology.boundary_loops(), 1);
  EXPECT_EQ(disk.topology.boundary_edges(), 16);
  EXPECT_EQ(disk.topology.components(), 1);
  EXPECT_TRUE(disk.geometry.planar());

  testing::octahedron(2, v, t);
  for (auto &p : v)
    p = testing::sphere_projection(p);
  Mesh sphere = build_mesh(linear_mesh(v, t));
  EXPECT_EQ(sphere.topology.euler_characteristic(), 2);
  EXPECT_EQ(sphere.topology.boundary_loops(), 0);
  EXPECT_TRUE(sphere.topology.orientable());

  // Annulus: the 4x4 grid without its 2x2 centre block... (remove the 8 central triangles).
  testing::square_grid(4, rng, v, t);
  std::vector<std::array<int64_t, 3>> ring;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const int sq = static_cast<int>(i / 2), si = sq % 4, sj = sq / 4;
    if (!(si >= 1 && si <= 2 && sj >= 1 && sj <= 2))
      ring.push_back(t[i]);
  }
  Mesh annulus = build_mesh(linear_mesh(v, ring));
  EXPECT_EQ(annulus.topology.euler_characteristic(), 0);
  EXPECT_EQ(annulus.topology.boundary_loops(), 2);
}

TEST(MeshChecks, ComponentsAndOrientation) {
  // Consistently oriented input (the common case, no walk from cell to cell): two disks are two
  // components, every cell of parity +1. Cells given in mixed orientations: the walk orients
  // them, one component, no inverted cell. A Moebius strip cannot be oriented (a warning).
  std::mt19937_64 rng(4);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(3, rng, v, t);
  std::vector<Vec3> v2 = v;
  std::vector<std::array<int64_t, 3>> t2 = t;
  const int64_t shift = static_cast<int64_t>(v.size());
  for (const Vec3 &p : v)
    v2.push_back({p[0] + 5, p[1], p[2]});
  for (const auto &tri : t)
    t2.push_back({tri[0] + shift, tri[1] + shift, tri[2] + shift});
  const Mesh two = build_mesh(linear_mesh(v2, t2));
  EXPECT_EQ(two.topology.components(), 2);
  EXPECT_TRUE(two.topology.orientable());

  std::vector<std::array<int64_t, 3>> mixed = t;
  for (std::size_t i = 0; i < mixed.size(); i += 2)
    std::swap(mixed[i][1], mixed[i][2]);
  const Mesh m = build_mesh(linear_mesh(v, mixed), {false});
  EXPECT_EQ(m.topology.components(), 1);
  EXPECT_TRUE(m.topology.orientable());
  EXPECT_FALSE(m.problems.has_errors()) << m.problems.summary();
  EXPECT_EQ(m.problems.count(Problem::InvertedCell), 0);

  // Moebius strip: a band of 8 quads (16 triangles) whose ends are glued with a half twist.
  std::vector<Vec3> band;
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, w = 0.3 * std::cos(a / 2), h = 0.3 * std::sin(a / 2);
    band.push_back({(1 + w) * std::cos(a), (1 + w) * std::sin(a), h});
    band.push_back({(1 - w) * std::cos(a), (1 - w) * std::sin(a), -h});
  }
  std::vector<std::array<int64_t, 3>> strip;
  for (int i = 0; i < n; ++i) {
    const int64_t a0 = 2 * i, a1 = 2 * i + 1;
    // The last quad joins the first rung crosswise (the half twist).
    const int64_t b0 = i + 1 < n ? 2 * (i + 1) : 1, b1 = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    strip.push_back({a0, b0, a1});
    strip.push_back({a1, b0, b1});
  }
  const Mesh mobius = build_mesh(linear_mesh(band, strip), {false});
  EXPECT_FALSE(mobius.topology.orientable());
  EXPECT_EQ(mobius.problems.count(Problem::NonOrientable), 1) << mobius.problems.summary();
  EXPECT_EQ(mobius.topology.components(), 1);
}

TEST(MeshChecks, DegreeAboveTheLimitIsRefused) {
  // A degree-21 cell (253 nodes) from a caller that built the MeshInput itself: a clear error,
  // before any conversion or per-edge buffer sized for degree 20 sees it.
  const int d = kMaxDegree + 1;
  MeshInput m;
  for (int i = 0; i < lattice_size(d); ++i) {
    const auto q = lattice_point(d, i);
    m.points.push_back({static_cast<double>(q[0]) / d, static_cast<double>(q[1]) / d, 0});
    m.values.push_back(static_cast<double>(q[0] * q[1]));
  }
  std::vector<int64_t> nodes(static_cast<std::size_t>(lattice_size(d)));
  std::iota(nodes.begin(), nodes.end(), 0);
  m.add_cell(d, nodes.data());
  const Mesh r = build_mesh(m, {false});
  EXPECT_TRUE(message_contains(r, Problem::UnsupportedDegree, "cell 0 has degree 21"))
      << r.problems.summary();
  EXPECT_FALSE(r.complete);
  EXPECT_THROW(build_mesh(m), Error);
}

TEST(MeshChecks, NonManifoldEdge) {
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  const Mesh m = build_mesh(linear_mesh(v, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}), {false});
  EXPECT_EQ(m.problems.count(Problem::NonManifoldEdge), 1);
  EXPECT_TRUE(message_contains(m, Problem::NonManifoldEdge, "shared by 3 cells (0, 1, 2)"));
  EXPECT_THROW(build_mesh(linear_mesh(v, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}})), Error);
}

TEST(MeshChecks, PinchedVertex) {
  // Two triangles touching at one vertex (a bow tie).
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  const Mesh m = build_mesh(linear_mesh(v, {{0, 1, 2}, {0, 3, 4}}), {false});
  EXPECT_GE(m.problems.count(Problem::NonManifoldVertex), 1);
  EXPECT_TRUE(message_contains(m, Problem::NonManifoldVertex, "point 0"));
}

TEST(MeshChecks, InteriorPinchedVertex) {
  // Two closed octahedra touching at one vertex (point 0): every edge has two cells and no
  // boundary anywhere, so counting cells and edges around point 0 cannot tell its two fans of
  // four cells from one of eight; walking around it can.
  const std::vector<Vec3> v = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0},  {-1, 0, 0}, {0, -1, 0}, {0, 0, -1},
                               {1, 0, 2}, {0, 1, 2}, {-1, 0, 2}, {0, -1, 2}, {0, 0, 3}};
  const std::vector<std::array<int64_t, 3>> lower = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1},
                                                     {5, 2, 1}, {5, 3, 2}, {5, 4, 3}, {5, 1, 4}};
  const std::vector<std::array<int64_t, 3>> upper = {
      {0, 7, 6}, {0, 8, 7}, {0, 9, 8}, {0, 6, 9}, {10, 6, 7}, {10, 7, 8}, {10, 8, 9}, {10, 9, 6}};
  std::vector<std::array<int64_t, 3>> both = lower;
  both.insert(both.end(), upper.begin(), upper.end());
  for (int threads : {1, 2}) {
    const Mesh m = build_mesh(linear_mesh(v, both), {.throw_on_error = false, .threads = threads});
    EXPECT_EQ(m.problems.count(Problem::NonManifoldVertex), 1) << m.problems.summary();
    EXPECT_TRUE(message_contains(m, Problem::NonManifoldVertex,
                                 "point 0: its 8 cells form more than one fan (4 of them"));
  }
  // Either octahedron alone is a sphere: nothing to report.
  EXPECT_EQ(build_mesh(linear_mesh(v, lower), {false}).problems.count(Problem::NonManifoldVertex),
            0);
}

TEST(MeshChecks, SeparateComponentsMayBeListedEitherWayRound) {
  // Two squares side by side, not touching: the first listed counter-clockwise, the second
  // clockwise (as a piece of a partitioned mesh may be, or a DOLFINx mesh in two parts). Neither
  // overlaps anything: no inverted cell. An inverted cell inside the larger one is still found.
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}};
  const std::vector<std::array<int64_t, 3>> t = {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6}};
  Mesh two = build_mesh(linear_mesh(v, t), {false});
  EXPECT_EQ(two.topology.components(), 2);
  EXPECT_EQ(two.problems.count(Problem::InvertedCell), 0) << two.problems.summary();
  std::mt19937_64 rng(2);
  std::vector<Vec3> w;
  std::vector<std::array<int64_t, 3>> g;
  testing::square_grid(3, rng, w, g);
  w[5] = {0.9, 0.9, 0};
  const int64_t base = static_cast<int64_t>(w.size());
  for (int k = 0; k < 4; ++k) // a separate square, clockwise
    w.push_back({5.0 + (k == 1 || k == 2), (k >= 2) * 1.0, 0.0});
  g.push_back({base, base + 2, base + 1});
  g.push_back({base, base + 3, base + 2});
  Mesh both = build_mesh(linear_mesh(w, g), {false});
  EXPECT_GE(both.problems.count(Problem::InvertedCell), 1) << both.problems.summary();
  EXPECT_FALSE(
      message_contains(both, Problem::InvertedCell, "cell " + std::to_string(g.size() - 1) + " "))
      << both.problems.summary();
}

TEST(MeshChecks, InvertedAndZeroAreaCells) {
  std::mt19937_64 rng(2);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(3, rng, v, t);
  // Move interior vertex (1,1) across its neighbours: some cells flip.
  v[5] = {0.9, 0.9, 0};
  Mesh inverted = build_mesh(linear_mesh(v, t), {false});
  EXPECT_GE(inverted.problems.count(Problem::InvertedCell), 1) << inverted.problems.summary();
  // A cell whose corners are collinear.
  const std::vector<Vec3> w = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  Mesh flat = build_mesh(linear_mesh(w, {{0, 1, 2}, {0, 1, 3}}), {false});
  EXPECT_TRUE(message_contains(flat, Problem::ZeroArea, "cell 0")) << flat.problems.summary();
  // A consistently clockwise mesh is fine.
  testing::square_grid(3, rng, v, t);
  for (auto &tri : t)
    std::swap(tri[1], tri[2]);
  Mesh cw = build_mesh(linear_mesh(v, t), {false});
  EXPECT_FALSE(cw.problems.has_errors()) << cw.problems.summary();
}

// A P1 cell next to a P2 cell across the square's diagonal (issue 27, item 13): where the P2
// cell's midpoint of the shared edge leaves the straight line, the two cells do not meet (a
// geometric gap) and the mesh check says so; on the line, or with float32-rounded coordinates
// far from the origin, there is none. The field (x + 2y at the nodes, the midpoint's value the P1
// cell's) is continuous either way.
MeshInput p1_next_to_p2(Vec3 diagonal_midpoint, Vec3 shift = {0, 0, 0}, bool round = false) {
  MeshInput m;
  m.points = {{0, 0, 0},         {1, 0, 0},   {1, 1, 0},  {0, 1, 0},
              diagonal_midpoint, {0.5, 1, 0}, {0, 0.5, 0}};
  for (auto &p : m.points)
    for (int j = 0; j < 3; ++j)
      p[j] = round ? static_cast<double>(static_cast<float>(p[j] + shift[j])) : p[j] + shift[j];
  for (const auto &p : m.points)
    m.values.push_back(p[0] + 2 * p[1]);
  // The midpoint's value is the P1 cell's there, wherever the node sits.
  m.values[4] = (m.values[0] + m.values[2]) / 2;
  const int64_t a[3] = {0, 1, 2};
  // Lattice order: corner 0, edge 0's midpoint, corner 1, edge 2's midpoint, edge 1's, corner 2.
  const int64_t b[6] = {0, 4, 2, 6, 5, 3};
  m.add_cell(1, a);
  m.add_cell(2, b);
  m.source = "gap";
  return m;
}

TEST(MeshChecks, CurvedEdgeNextToStraightEdgeIsAGap) {
  const Mesh gap = build_mesh(p1_next_to_p2({0.45, 0.55, 0}), {false});
  EXPECT_EQ(gap.problems.count(Problem::GeometricGap), 1) << gap.problems.summary();
  EXPECT_TRUE(message_contains(gap, Problem::GeometricGap,
                               "cells 0 (degree 1 map) and 1 (degree 2 map) do not meet along "
                               "their shared edge (points 0-2): their edge curves differ by up to"))
      << gap.problems.summary();
  EXPECT_EQ(gap.problems.count(Problem::DiscontinuousEdge), 0) << gap.problems.summary();
  EXPECT_TRUE(problem_info(Problem::GeometricGap).forceable);
  EXPECT_THROW(build_mesh(p1_next_to_p2({0.45, 0.55, 0})), Error);
  // Barely off the line (1e-4 of the diagonal): still a gap.
  const Mesh small = build_mesh(p1_next_to_p2({0.5, 0.5 + 1.4e-4, 0}), {false});
  EXPECT_EQ(small.problems.count(Problem::GeometricGap), 1) << small.problems.summary();
  // On the straight line: no gap.
  const Mesh straight = build_mesh(p1_next_to_p2({0.5, 0.5, 0}), {false});
  EXPECT_FALSE(straight.problems.has_errors()) << straight.problems.summary();
  // float32 coordinates around (1e4, 1e4): rounding is no gap.
  const Mesh rounded = build_mesh(p1_next_to_p2({0.5, 0.5, 0}, {1e4, 1e4, 0}, true), {false});
  EXPECT_FALSE(rounded.problems.has_errors()) << rounded.problems.summary();
}

TEST(MeshChecks, BadInputData) {
  std::mt19937_64 rng(3);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(2, rng, v, t);
  MeshInput nan_value = linear_mesh(v, t);
  nan_value.values[4] = std::numeric_limits<double>::quiet_NaN();
  Mesh a = build_mesh(nan_value, {false});
  EXPECT_TRUE(message_contains(a, Problem::NonFiniteValue, "point 4"));

  MeshInput inf_point = linear_mesh(v, t);
  inf_point.points[2][1] = std::numeric_limits<double>::infinity();
  Mesh b = build_mesh(inf_point, {false});
  EXPECT_TRUE(message_contains(b, Problem::NonFiniteCoordinate, "point 2"));

  MeshInput missing = linear_mesh(v, t);
  missing.cell_nodes[7] = 99;
  Mesh c = build_mesh(missing, {false});
  EXPECT_TRUE(message_contains(c, Problem::MissingNode, "cell 2 refers to point 99"));
  EXPECT_FALSE(c.complete);
  try {
    build_mesh(missing);
    FAIL();
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("cell 2 refers to point 99"), std::string::npos);
  }

  MeshInput repeated = linear_mesh(v, t);
  repeated.cell_nodes[1] = repeated.cell_nodes[0];
  Mesh d = build_mesh(repeated, {false});
  EXPECT_TRUE(message_contains(d, Problem::InconsistentNodes, "cell 0 uses point"));

  MeshInput empty;
  Mesh e = build_mesh(empty, {false});
  EXPECT_EQ(e.problems.count(Problem::EmptyMesh), 1);
}

TEST(MeshChecks, TinyValueRangeIsRefused) {
  // Values spanning less than kMinValueRange (products of derivatives would underflow): refused
  // with the finite values' range. On a grid of 20,000 points the range is gathered from several
  // blocks of points, its ends in different ones; a NaN elsewhere does not enter it.
  std::mt19937_64 rng(4);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(140, rng, v, t);
  MeshInput tiny = linear_mesh(v, t);
  ASSERT_GT(tiny.points.size(), 3 * 4096u);
  for (std::size_t i = 0; i < tiny.values.size(); ++i)
    tiny.values[i] = 1e-160 * static_cast<double>((i * 7919) % 1000);
  tiny.values[100] = 5e-145;    // the largest, in the first block
  tiny.values[15000] = -2e-145; // the smallest, in the fourth
  tiny.values[9000] = std::numeric_limits<double>::quiet_NaN();
  for (int threads : {1, 2}) {
    const Mesh m = build_mesh(tiny, {.throw_on_error = false, .threads = threads});
    EXPECT_TRUE(message_contains(m, Problem::ValueRangeTooSmall, "from -2e-145 to 5e-145"))
        << m.problems.summary();
    EXPECT_TRUE(message_contains(m, Problem::NonFiniteValue, "point 9000"));
  }
  // A range of 1e-100 is accepted.
  MeshInput small = linear_mesh(v, t);
  for (std::size_t i = 0; i < small.values.size(); ++i)
    small.values[i] = 1e-100 * v[i][0];
  EXPECT_EQ(build_mesh(small, {false}).problems.count(Problem::ValueRangeTooSmall), 0);
}

TEST(MeshChecks, CurvedCellFoldedInside) {
  // A quadratic cell whose hypotenuse midpoint node is pulled across the opposite corner.
  MeshInput m;
  m.points = {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {0, 0.5, 0}, {-0.5, -0.5, 0}, {0, 1, 0}};
  m.values = {0, 1, 2, 3, 4, 5};
  const int64_t nodes[6] = {0, 1, 2, 3, 4, 5};
  m.add_cell(2, nodes);
  Mesh r = build_mesh(m, {false});
  EXPECT_EQ(r.problems.count(Problem::FoldedCell), 1) << r.problems.summary();
  EXPECT_EQ(r.geometry.curved_cells(), 1);
}

// One quadratic cell, (0,0), (1,0), (0,1) with its first edge's middle node moved to (0.5, y)
// and, with lift, its third edge's middle node raised to z = lift (a surface cell). Whether
// check_geometry calls it folded is compared with a dense sampling of the Jacobian determinant
// (planar) or of the normal against the normal at the centre (surface): the certified fast
// path must agree with the brute force wherever the sampled minimum is clearly away from 0.
TEST(MeshChecks, CurvedCellChecksAgreeWithDenseSampling) {
  int folded_cases = 0, sound_cases = 0;
  for (double lift : {0.0, 0.4})
    for (int step = -30; step <= 30; ++step) {
      const double y = 0.05 * step;
      MeshInput m;
      m.points = {{0, 0, 0}, {0.5, y, 0}, {1, 0, 0}, {0, 0.5, lift}, {0.5, 0.5, 0}, {0, 1, 0}};
      m.values = {0, 1, 2, 3, 4, 5};
      const int64_t nodes[6] = {0, 1, 2, 3, 4, 5};
      m.add_cell(2, nodes);
      const Mesh r = build_mesh(m, {false});
      ASSERT_TRUE(r.complete) << r.problems.summary();
      auto normal = [&](double u, double v) {
        const auto j = r.geometry.jacobian(0, u, v);
        return Vec3{j[0][1] * j[1][2] - j[0][2] * j[1][1], j[0][2] * j[1][0] - j[0][0] * j[1][2],
                    j[0][0] * j[1][1] - j[0][1] * j[1][0]};
      };
      const Vec3 n0 = normal(1.0 / 3, 1.0 / 3);
      double lo = INFINITY, hi = -INFINITY;
      const int n = 400;
      for (int a = 0; a <= n; ++a)
        for (int b = 0; a + b <= n; ++b) {
          const Vec3 nv = normal(double(a) / n, double(b) / n);
          // Planar: the determinant (the normal's z); surface: the normal against the centre's.
          const double s = lift == 0 ? nv[2] : nv[0] * n0[0] + nv[1] * n0[1] + nv[2] * n0[2];
          lo = std::min(lo, s);
          hi = std::max(hi, s);
        }
      if (std::abs(lo) < 1e-3 || hi <= 0)
        continue; // at the threshold, or wholly inverted (no neighbour to disagree with)
      const bool folded = lo < 0;
      // A fold may pass through a point where the map is singular (zero area there): either
      // report is right then.
      EXPECT_EQ(r.problems.count(Problem::FoldedCell) + r.problems.count(Problem::ZeroArea),
                folded ? 1 : 0)
          << "y " << y << ", lift " << lift << ": sampled " << lo << " .. " << hi << "\n"
          << r.problems.summary();
      (folded ? folded_cases : sound_cases)++;
    }
  // Both outcomes occur, planar and curved surface alike.
  EXPECT_GT(folded_cases, 10);
  EXPECT_GT(sound_cases, 10);
}

} // namespace
} // namespace hoct

namespace hoct {
namespace {

// coincident_points against the O(n^2) definition: random points, some in clusters closer than
// the tolerance (crowded cells of more than 64 points among them), some straddling the grid's
// cell faces at distances just below and above the tolerance, in 2D and 3D.
TEST(DuplicatePoints, CoincidentPointsAcrossCoarseCellCorners) {
  // Pairs 0.85 tolerance apart straddling a corner of the coarse grid (cells of 1024
  // tolerances from the smallest coordinates, here those of the first point) with mixed signs:
  // one point lies above the corner along one axis and below it along another, so it is near an
  // upper face of its cell and a lower face, and only checking both sides finds its partner.
  std::mt19937_64 rng(13);
  const double tol = 1e-6, h = 1024 * tol;
  std::vector<Vec3> pts = {{-2, -2, -2}};
  for (int i = 0; i < 60; ++i) {
    Vec3 corner;
    for (int ax = 0; ax < 3; ++ax)
      corner[ax] = -2 + h * static_cast<double>(100 + rng() % 3000);
    const int a = i % 3, b = (i + 1) % 3; // the two axes with opposite offsets
    Vec3 p = corner, q = corner;
    p[a] -= 0.3 * tol;
    p[b] += 0.3 * tol;
    q[a] += 0.3 * tol;
    q[b] -= 0.3 * tol;
    pts.push_back(p);
    pts.push_back(q);
  }
  std::vector<int64_t> cand(pts.size());
  std::iota(cand.begin(), cand.end(), 0);
  const std::vector<int64_t> got = coincident_points(pts, cand, tol);
  EXPECT_EQ(got[0], 0);
  for (std::size_t i = 1; i < pts.size(); i += 2) {
    EXPECT_EQ(got[i], static_cast<int64_t>(i)) << "pair " << i / 2;
    EXPECT_EQ(got[i + 1], static_cast<int64_t>(i)) << "pair " << i / 2;
  }
}

TEST(DuplicatePoints, CoincidentPointsMatchBruteForce) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int trial = 0; trial < 12; ++trial) {
    const double tol = trial % 2 ? 1e-3 : 1e-6;
    const bool flat = trial % 3 == 0;
    std::vector<Vec3> pts;
    auto add = [&](const Vec3 &p) { pts.push_back({p[0], p[1], flat ? 0.0 : p[2]}); };
    for (int i = 0; i < 300; ++i)
      add({U(rng), U(rng), U(rng)});
    // A crowded cluster (all within 1000 tolerances) with chains below the tolerance.
    const Vec3 c{U(rng), U(rng), U(rng)};
    for (int i = 0; i < 150; ++i)
      add({c[0] + 400 * tol * U(rng), c[1] + 400 * tol * U(rng), c[2] + 400 * tol * U(rng)});
    // A tight one (chains of points closer than the tolerance).
    const Vec3 t{U(rng), U(rng), U(rng)};
    for (int i = 0; i < 120; ++i)
      add({t[0] + 2 * tol * U(rng), t[1] + 2 * tol * U(rng), t[2] + 2 * tol * U(rng)});
    // Pairs at 0.9 and 1.1 tolerances in random directions around random points.
    for (int i = 0; i < 100; ++i) {
      const Vec3 p{U(rng), U(rng), U(rng)};
      Vec3 d{U(rng), U(rng), flat ? 0.0 : U(rng)};
      const double len = std::hypot(d[0], d[1], d[2]);
      const double r = (i % 2 ? 0.9 : 1.1) * tol / len;
      add(p);
      add({p[0] + r * d[0], p[1] + r * d[1], p[2] + r * d[2]});
    }
    std::vector<int64_t> cand(pts.size());
    std::iota(cand.begin(), cand.end(), 0);
    std::shuffle(cand.begin(), cand.end(), rng);
    const std::vector<int64_t> got = coincident_points(pts, cand, tol);
    // Brute force: components of the "closer than tol" graph, represented by their smallest id.
    const std::size_t n = cand.size();
    std::vector<int64_t> comp(n);
    std::iota(comp.begin(), comp.end(), 0);
    std::function<int64_t(int64_t)> find = [&](int64_t x) {
      return comp[x] == x ? x : comp[x] = find(comp[x]);
    };
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const Vec3 &p = pts[cand[i]], &q = pts[cand[j]];
        if ((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                (p[2] - q[2]) * (p[2] - q[2]) <=
            tol * tol)
          comp[find(static_cast<int64_t>(i))] = find(static_cast<int64_t>(j));
      }
    std::vector<int64_t> smallest(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
      int64_t &m = smallest[find(static_cast<int64_t>(i))];
      if (m < 0 || cand[i] < m)
        m = cand[i];
    }
    int64_t merged = 0;
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(got[i], smallest[find(static_cast<int64_t>(i))]) << "trial " << trial << " i " << i;
      merged += got[i] != cand[i];
    }
    EXPECT_GT(merged, 150) << trial; // the tight cluster and the 0.9-tolerance pairs
  }
}

} // namespace
} // namespace hoct
