// The mesh build on several threads: topology, problem reports and field equal the one-thread
// build bit for bit, on meshes large enough that every parallel pass runs on more than one
// thread (passes start a second thread only from 16k-65k items), and the counts match what the
// meshes are built to have.
#include "mesh/duplicate_points.hpp"
#include "mesh/field.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/topology.hpp"
#include "test_meshes.hpp"
#include "util/concurrent_sets.hpp"
#include "util/parallel_sort.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>
#include <random>

namespace hoct {
namespace {

constexpr int kGrid = 260; // 135,200 cells and 68,121 vertices per grid

// Squares removed from the grid (each leaves a hole: a boundary loop of its own).
bool is_hole(int i, int j) { return i % 50 == 25 && j % 50 == 25; }
constexpr int kHoles = 25;

struct Built {
  Topology topology;
  ProblemLog problems;
};

Built build(const MeshInput &in, int threads) {
  Built b;
  b.topology = Topology::build(in, b.problems, threads);
  return b;
}

void expect_same(const Topology &a, const Topology &b) {
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  ASSERT_EQ(a.num_edges(), b.num_edges());
  ASSERT_EQ(a.num_cells(), b.num_cells());
  for (int64_t v = 0; v < a.num_vertices(); ++v) {
    ASSERT_EQ(a.vertex_point(v), b.vertex_point(v)) << v;
    ASSERT_EQ(a.vertex_cell(v), b.vertex_cell(v)) << v;
    ASSERT_EQ(a.vertex_corner(v), b.vertex_corner(v)) << v;
  }
  for (int64_t e = 0; e < a.num_edges(); ++e) {
    ASSERT_EQ(a.edge_vertices(e), b.edge_vertices(e)) << e;
    ASSERT_EQ(a.edge_cell_count(e), b.edge_cell_count(e)) << e;
    for (int i = 0; i < a.edge_cell_count(e); ++i)
      ASSERT_EQ(a.edge_cells_begin(e)[i], b.edge_cells_begin(e)[i]) << e;
  }
  for (int64_t c = 0; c < a.num_cells(); ++c) {
    ASSERT_EQ(a.cell_vertices(c), b.cell_vertices(c)) << c;
    ASSERT_EQ(a.cell_parity(c), b.cell_parity(c)) << c;
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(a.cell_edge(c, k), b.cell_edge(c, k)) << c;
      ASSERT_EQ(a.edge_reversed(c, k), b.edge_reversed(c, k)) << c;
    }
  }
  EXPECT_EQ(a.boundary_loops(), b.boundary_loops());
  EXPECT_EQ(a.boundary_edges(), b.boundary_edges());
  EXPECT_EQ(a.components(), b.components());
  EXPECT_EQ(a.orientable(), b.orientable());
}

// Two grids side by side (two components), with holes, as degree-`d` cells.
void two_grids(std::mt19937_64 &rng, std::vector<Vec3> &v, std::vector<std::array<int64_t, 3>> &t) {
  std::vector<Vec3> gv;
  std::vector<std::array<int64_t, 3>> gt;
  testing::square_grid(kGrid, rng, gv, gt);
  v.clear();
  t.clear();
  for (int copy = 0; copy < 2; ++copy) {
    const int64_t shift = static_cast<int64_t>(v.size());
    for (const Vec3 &p : gv)
      v.push_back({p[0] + 2 * copy, p[1], p[2]});
    for (std::size_t i = 0; i < gt.size(); ++i) {
      const int sq = static_cast<int>(i / 2);
      if (!is_hole(sq % kGrid, sq / kGrid))
        t.push_back({gt[i][0] + shift, gt[i][1] + shift, gt[i][2] + shift});
    }
  }
}

// The two grids as Lagrange cells of degree degree_of(c), with random node values.
MeshInput two_grid_mesh(uint64_t seed, const std::function<int(int64_t)> &degree_of) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  two_grids(rng, v, t);
  return testing::lagrange_mesh(v, t, degree_of, nullptr, nullptr, rng);
}

TEST(Topology, SameOnAnyThreadCount) {
  // Consistently oriented: the components by concurrent disjoint sets.
  const MeshInput in = two_grid_mesh(11, [](int64_t c) { return 1 + static_cast<int>(c % 2); });
  const Built one = build(in, 1), two = build(in, 2), three = build(in, 3);
  // What the mesh is built to be: two disks with kHoles holes each.
  const int64_t squares = int64_t{kGrid} * kGrid - kHoles;
  EXPECT_EQ(one.topology.num_cells(), 2 * 2 * squares);
  EXPECT_EQ(one.topology.num_vertices(), 2 * int64_t{kGrid + 1} * (kGrid + 1));
  EXPECT_EQ(one.topology.components(), 2);
  EXPECT_EQ(one.topology.boundary_loops(), 2 * (1 + kHoles));
  EXPECT_EQ(one.topology.boundary_edges(), 2 * (4 * kGrid + 4 * kHoles));
  EXPECT_EQ(one.topology.euler_characteristic(), 2 * (1 - kHoles));
  EXPECT_TRUE(one.problems.empty()) << one.problems.summary();
  expect_same(one.topology, two.topology);
  expect_same(one.topology, three.topology);
  EXPECT_TRUE(two.problems.empty()) << two.problems.summary();

  // The field on those topologies: the same coefficients on any thread count.
  ProblemLog p1, p2;
  const Field f1 = Field::build(in, one.topology, p1, 1),
              f2 = Field::build(in, two.topology, p2, 2);
  ASSERT_EQ(f1.num_cells(), f2.num_cells());
  for (int64_t c = 0; c < f1.num_cells(); ++c) {
    const auto a = f1.coefficients(c), b = f2.coefficients(c);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size_bytes()), 0) << c;
  }
  for (int64_t e = 0; e < one.topology.num_edges(); ++e) {
    const auto a = f1.edge_coefficients(e), b = f2.edge_coefficients(e);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size_bytes()), 0) << e;
  }
}

TEST(Topology, SameProblemsOnAnyThreadCount) {
  // Mixed orientations (the walk from cell to cell), and defects spread over the mesh: cells
  // with a repeated corner, extra cells on interior edges (non-manifold), bow ties at vertices
  // (a pinch), and node values that disagree across edges. Every report, its counts and its
  // first examples, equals the one-thread report.
  std::mt19937_64 rng(12);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  two_grids(rng, v, t);
  for (std::size_t i = 0; i < t.size(); i += 3)
    std::swap(t[i][1], t[i][2]);
  const int64_t grid_cells = static_cast<int64_t>(t.size());
  // A grid triangle's diagonal (interior: both triangles of a square have it) joins its lowest
  // and highest vertex ids; the local edge k along it.
  auto diagonal = [&](int64_t c) {
    const auto &tri = t[static_cast<std::size_t>(c)];
    const int64_t lo = std::min({tri[0], tri[1], tri[2]}), hi = std::max({tri[0], tri[1], tri[2]});
    for (int k = 0; k < 3; ++k)
      if (std::min(tri[k], tri[(k + 1) % 3]) == lo && std::max(tri[k], tri[(k + 1) % 3]) == hi)
        return k;
    return -1;
  };
  auto new_point = [&](double x, double y) {
    v.push_back({x, y, 1.0});
    return static_cast<int64_t>(v.size()) - 1;
  };
  for (int k = 0; k < 12; ++k) {
    const auto c = t[static_cast<std::size_t>(k * grid_cells / 12)];
    const int d = diagonal(k * grid_cells / 12);
    t.push_back({c[d], c[(d + 1) % 3], new_point(5.0 + k, 5.0)}); // a third cell on an edge
    t.push_back({c[(d + 2) % 3], new_point(6.0 + k, 6.0), new_point(6.0 + k, 7.0)}); // bow tie
    const int64_t a = new_point(8.0 + k, 8.0);
    t.push_back({a, a, new_point(8.0 + k, 9.0)}); // a repeated corner
  }
  MeshInput in = testing::lagrange_mesh(
      v, t, [](int64_t) { return 2; }, nullptr, nullptr, rng, /*rotate=*/false);
  // Discontinuous: ten cells get their own copy of their diagonal's middle node, with another
  // value.
  for (int64_t j = 0; j < 10; ++j) {
    const int64_t c = j * (grid_cells / 10) + 1001; // away from the cells given a third neighbour
    const int64_t node = in.cell_offsets[c] + edge_lattice_index(2, diagonal(c), 1);
    in.points.push_back(in.points[in.cell_nodes[node]]);
    in.values.push_back(in.values[in.cell_nodes[node]] + 1.0);
    in.cell_nodes[node] = static_cast<int64_t>(in.points.size()) - 1;
  }
  const Built one = build(in, 1), two = build(in, 2), three = build(in, 3);
  EXPECT_EQ(one.problems.count(Problem::NonManifoldEdge), 12);
  EXPECT_EQ(one.problems.count(Problem::RepeatedCorner), 12);
  EXPECT_GE(one.problems.count(Problem::NonManifoldVertex), 12);
  // The grids, and each added cell on its own (joined to nothing through a two-cell edge).
  EXPECT_EQ(one.topology.components(), 2 + 3 * 12);
  EXPECT_EQ(one.problems.summary(), two.problems.summary());
  EXPECT_EQ(one.problems.summary(), three.problems.summary());
  expect_same(one.topology, two.topology);
  expect_same(one.topology, three.topology);

  ProblemLog p1, p2;
  Field::build(in, one.topology, p1, 1);
  Field::build(in, two.topology, p2, 2);
  EXPECT_EQ(p1.count(Problem::DiscontinuousEdge), 10);
  EXPECT_EQ(p1.summary(), p2.summary());
}

TEST(MeshChecks, SameInputReportOnAnyThreadCount) {
  // Bad points and cells spread over a large input: the same verdict and report on 1, 2 and 3
  // threads, with the counts the input is built to have.
  MeshInput in = two_grid_mesh(13, [](int64_t) { return 2; });
  const int64_t np = static_cast<int64_t>(in.points.size());
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  for (int k = 0; k < 7; ++k) {
    in.points[static_cast<std::size_t>(k * np / 7)][1] = std::nan("");
    in.values[static_cast<std::size_t>(k * np / 7 + 3)] = 1e120;
    in.cell_nodes[in.cell_offsets[k * nc / 7 + 5] + 1] = np + k; // missing point
    in.cell_nodes[in.cell_offsets[k * nc / 7 + 9] + 4] =
        in.cell_nodes[in.cell_offsets[k * nc / 7 + 9] + 2]; // a node twice
  }
  ProblemLog one, two, three;
  const bool ok1 = check_input(in, one, 1);
  EXPECT_EQ(check_input(in, two, 2), ok1);
  EXPECT_EQ(check_input(in, three, 3), ok1);
  EXPECT_FALSE(ok1);
  EXPECT_EQ(one.count(Problem::NonFiniteCoordinate), 7);
  EXPECT_EQ(one.count(Problem::ValueOutOfRange), 7);
  EXPECT_EQ(one.count(Problem::MissingNode), 7);
  EXPECT_EQ(one.count(Problem::InconsistentNodes), 7);
  EXPECT_EQ(one.summary(), two.summary());
  EXPECT_EQ(one.summary(), three.summary());
}

TEST(DuplicatePoints, PlantedDuplicatesOnAnyThreadCount) {
  // 160,000 jittered lattice points one unit apart, with a copy 0.5 tolerances away planted next
  // to every 997th (found: same group) and one 2 tolerances away next to every 991st (not).
  // Candidates in ascending and in shuffled order, on 1, 2 and 3 threads: each point's group is
  // represented by its smallest id.
  const double tol = 1e-3;
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> J(-0.1, 0.1), U(-1, 1);
  std::vector<Vec3> pts;
  for (int j = 0; j < 400; ++j)
    for (int i = 0; i < 400; ++i)
      pts.push_back({i + J(rng), j + J(rng), J(rng)});
  const int64_t lattice = static_cast<int64_t>(pts.size());
  std::vector<int64_t> expected(pts.size());
  std::iota(expected.begin(), expected.end(), 0);
  auto plant = [&](int64_t p, double distance) {
    Vec3 d{U(rng), U(rng), U(rng)};
    const double len = std::hypot(d[0], d[1], d[2]);
    const Vec3 &q = pts[static_cast<std::size_t>(p)];
    pts.push_back(
        {q[0] + distance * d[0] / len, q[1] + distance * d[1] / len, q[2] + distance * d[2] / len});
    expected.push_back(distance < tol ? p : static_cast<int64_t>(pts.size()) - 1);
  };
  for (int64_t p = 0; p < lattice; p += 997)
    plant(p, 0.5 * tol);
  for (int64_t p = 5; p < lattice; p += 991)
    plant(p, 2 * tol);
  std::vector<int64_t> ascending(pts.size());
  std::iota(ascending.begin(), ascending.end(), 0);
  std::vector<int64_t> shuffled = ascending;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  for (int threads : {1, 2, 3}) {
    const std::vector<int64_t> a = coincident_points(pts, ascending, tol, threads);
    ASSERT_EQ(a, expected) << threads;
    const std::vector<int64_t> b = coincident_points(pts, shuffled, tol, threads);
    for (std::size_t i = 0; i < shuffled.size(); ++i)
      ASSERT_EQ(b[i], expected[static_cast<std::size_t>(shuffled[i])]) << threads << " " << i;
  }
}

// Folds quadratic cell c: the middle node of its first edge pulled past the opposite corner.
void fold(MeshInput &in, int64_t c) {
  const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
  const Vec3 far = in.points[nodes[corner_index(2, 2)]];
  Vec3 &p = in.points[nodes[edge_lattice_index(2, 0, 1)]];
  for (int i = 0; i < 3; ++i)
    p[i] += 3 * (far[i] - p[i]);
}

// check_geometry on 1, 2 and 3 threads: the same report.
void expect_same_geometry_report(const MeshInput &in, Problem expected_kind) {
  ProblemLog build_log;
  const Topology topo = Topology::build(in, build_log, 2);
  const Geometry g = Geometry::build(in, 2);
  ProblemLog one, two, three;
  check_geometry(g, topo, one, 1);
  check_geometry(g, topo, two, 2);
  check_geometry(g, topo, three, 3);
  EXPECT_GT(one.count(expected_kind), 0) << one.summary();
  EXPECT_EQ(one.summary(), two.summary());
  EXPECT_EQ(one.summary(), three.summary());
}

TEST(MeshChecks, SameGeometryReportOnAnyThreadCount) {
  // Planar: folded curved cells and inverted cells (a vertex pulled across its neighbours)
  // spread over the grids, quadratic and linear.
  MeshInput plane = two_grid_mesh(14, [](int64_t c) { return 1 + static_cast<int>(c % 2); });
  const int64_t nc = static_cast<int64_t>(plane.num_cells());
  for (int k = 0; k < 9; ++k)
    fold(plane, (k * nc / 9 + 17) | 1); // odd cells are the quadratic ones
  for (int k = 0; k < 5; ++k) {
    const int64_t c = k * nc / 5 + 1001;
    Vec3 &p = plane.points[plane.cell_nodes[plane.cell_offsets[c] +
                                            corner_index(plane.cell_degree[c], 0)]];
    p[0] += 4.0 / kGrid;
  }
  expect_same_geometry_report(plane, Problem::InvertedCell);
  expect_same_geometry_report(plane, Problem::FoldedCell);
  // A surface: a sphere of 67,712 cells, some folded.
  std::mt19937_64 rng(15);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::octahedron(92, v, t);
  MeshInput sphere = testing::lagrange_mesh(
      v, t, [](int64_t) { return 2; }, testing::sphere_projection, nullptr, rng);
  const int64_t ns = static_cast<int64_t>(sphere.num_cells());
  for (int k = 0; k < 7; ++k)
    fold(sphere, k * ns / 7 + 3);
  expect_same_geometry_report(sphere, Problem::FoldedCell);
}

TEST(MeshChecks, CurvedSurfaceCellsFoldedAreAllFoundAndNoOthers) {
  // Curved spheres (quadratic and cubic cells): no cell is reported, most are certified by their
  // normal's Bernstein coefficients. Then 7 quadratic cells folded: exactly those 7.
  for (int degree : {2, 3}) {
    std::mt19937_64 rng(16);
    std::vector<Vec3> v;
    std::vector<std::array<int64_t, 3>> t;
    testing::octahedron(24, v, t);
    MeshInput sphere = testing::lagrange_mesh(
        v, t, [&](int64_t) { return degree; }, testing::sphere_projection, nullptr, rng);
    ProblemLog log;
    const Topology topo = Topology::build(sphere, log, 1);
    ASSERT_TRUE(Geometry::build(sphere, 1).curved_cells() > 0);
    check_geometry(Geometry::build(sphere, 1), topo, log, 1);
    EXPECT_EQ(log.summary(), ProblemLog().summary()) << "degree " << degree;
    if (degree != 2)
      continue;
    const int64_t nc = static_cast<int64_t>(sphere.num_cells());
    for (int k = 0; k < 7; ++k)
      fold(sphere, k * nc / 7 + 3);
    ProblemLog folded;
    check_geometry(Geometry::build(sphere, 1), topo, folded, 1);
    EXPECT_EQ(folded.count(Problem::FoldedCell), 7) << folded.summary();
  }
}

TEST(BoundingBox, SameBoxOnAnyThreadCount) {
  // 3 million points (several per thread at the parallel grain) with their extremes in different
  // thirds: the box of a plain loop, on 1, 2 and 3 threads.
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> points(3000000);
  for (auto &p : points)
    p = {u(rng), 5 * u(rng), 1e-3 * u(rng)};
  points[10] = {-3, 0, 0};
  points[1500000] = {0, 7, 0};
  points[2999999] = {0, 0, -0.5};
  Vec3 lo = points[0], hi = points[0];
  for (const auto &p : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  for (int threads : {1, 2, 3}) {
    const auto box = bounding_box(points, threads);
    EXPECT_EQ(box[0], lo) << threads;
    EXPECT_EQ(box[1], hi) << threads;
    EXPECT_DOUBLE_EQ(bounding_box_diagonal(points, threads),
                     std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
  }
  EXPECT_EQ(bounding_box_diagonal({}, 2), 0);
}

TEST(ConcurrentSets, SamePartitionAsSerialUnions) {
  // Random unions from two threads: the same sets as uniting one by one, each rooted at its
  // smallest element.
  const int64_t n = 200000;
  std::mt19937_64 rng(3);
  std::vector<std::pair<int64_t, int64_t>> pairs(150000);
  for (auto &[a, b] : pairs) {
    a = static_cast<int64_t>(rng() % n);
    b = static_cast<int64_t>(rng() % n);
  }
  ConcurrentSets sets(n, 2);
  parallel_for(static_cast<int64_t>(pairs.size()), 2, [&](int64_t begin, int64_t end, int) {
    for (int64_t i = begin; i < end; ++i)
      sets.unite(pairs[i].first, pairs[i].second);
  });
  // The serial reference: labels by repeated relaxation to the smallest member.
  std::vector<int64_t> label(n);
  for (int64_t x = 0; x < n; ++x)
    label[x] = x;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto &[a, b] : pairs) {
      const int64_t m = std::min(label[a], label[b]);
      if (label[a] != m || label[b] != m) {
        label[a] = label[b] = m;
        changed = true;
      }
    }
  }
  int64_t roots = 0;
  for (int64_t x = 0; x < n; ++x) {
    ASSERT_EQ(sets.find(x), label[x]) << x;
    roots += label[x] == x;
  }
  EXPECT_EQ(sets.count(2), roots);
}

TEST(ParallelSort, EqualsStdSort) {
  // Pieces sorted on threads and merged in rounds (2, 3 and 5 pieces: one merge, an odd piece
  // left for a round, three rounds): the same sequence as std::sort.
  std::mt19937_64 rng(5);
  std::vector<std::pair<int64_t, int64_t>> keys(400000);
  for (std::size_t i = 0; i < keys.size(); ++i)
    keys[i] = {static_cast<int64_t>(rng() % 1000), static_cast<int64_t>(i)};
  auto expected = keys;
  std::sort(expected.begin(), expected.end());
  for (int threads : {1, 2, 3, 5}) {
    auto got = keys;
    parallel_sort(got.begin(), got.end(), threads);
    EXPECT_EQ(got, expected) << threads;
  }
}

} // namespace
} // namespace hoct
