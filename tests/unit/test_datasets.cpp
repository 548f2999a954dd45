// The synthetic datasets (src/datasets): sizes, degrees, determinism per seed, conforming shared
// edges, orientation and shape of the cells, the sphere's exact nodes, the conductor's plateau and
// ridge cells, and the two-triangle quintic's critical points. These are checked from the generated
// MeshInput alone, with geometry written here; two last tests make sure the library's own mesh
// checks (build_mesh) accept every dataset at several sizes and degrees, and that the exact tree
// sees the features the datasets are designed to have.
#include "datasets/datasets.hpp"
#include "datasets/seeded_random.hpp"
#include "exact/exact_contour_tree.hpp"
#include "mesh/mesh.hpp"
#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <vector>

namespace hoct {
namespace {

MeshInput make(const std::string &name, long long cells = 0, int degree = 0, uint64_t seed = 1) {
  DatasetOptions o;
  o.cells = cells;
  o.degree = degree;
  o.seed = seed;
  return generate_dataset(name, o);
}

// Small but representative sizes, to keep the tests quick (0: the default).
long long small_cells(const std::string &name) {
  return name == "heater"                      ? 1500
         : name == "conductor"                 ? 1200
         : name == "random" || name == "plate" ? 3000
                                               : 0;
}

bool is_planar(const std::string &name) { return name != "sphere" && name != "heater"; }

const int64_t *nodes_of(const MeshInput &m, std::size_t c) {
  return &m.cell_nodes[static_cast<std::size_t>(m.cell_offsets[c])];
}

Vec3 sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3 &a, const Vec3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3 &a) { return std::sqrt(dot(a, a)); }

// The lattice sub-triangles of a degree-d cell as canonical index triples, each oriented like
// the cell: (a,b),(a+1,b),(a,b+1) and (a+1,b),(a+1,b+1),(a,b+1).
std::vector<std::array<int, 3>> sub_triangles(int d) {
  std::vector<std::array<int, 3>> t;
  for (int b = 0; b < d; ++b)
    for (int a = 0; a + b < d; ++a) {
      t.push_back({lattice_index(d, a, b), lattice_index(d, a + 1, b), lattice_index(d, a, b + 1)});
      if (a + b + 1 < d)
        t.push_back({lattice_index(d, a + 1, b), lattice_index(d, a + 1, b + 1),
                     lattice_index(d, a, b + 1)});
    }
  return t;
}

// Well-formed arrays: offsets, degrees, node counts, ids in range, no id repeated in a cell,
// every point used, finite data.
void expect_well_formed(const MeshInput &m, int degree, const std::string &name) {
  ASSERT_EQ(m.cell_offsets.size(), m.num_cells() + 1) << name;
  ASSERT_EQ(m.values.size(), m.points.size()) << name;
  ASSERT_EQ(m.cell_offsets.front(), 0) << name;
  ASSERT_EQ(static_cast<std::size_t>(m.cell_offsets.back()), m.cell_nodes.size()) << name;
  std::vector<char> used(m.num_points(), 0);
  for (std::size_t c = 0; c < m.num_cells(); ++c) {
    ASSERT_EQ(m.cell_degree[c], degree) << name << " cell " << c;
    ASSERT_EQ(m.cell_offsets[c + 1] - m.cell_offsets[c], lattice_size(degree))
        << name << " cell " << c;
    const int64_t *n = nodes_of(m, c);
    std::set<int64_t> distinct(n, n + lattice_size(degree));
    ASSERT_EQ(distinct.size(), static_cast<std::size_t>(lattice_size(degree)))
        << name << " cell " << c << " repeats a node";
    for (int i = 0; i < lattice_size(degree); ++i) {
      ASSERT_GE(n[i], 0) << name;
      ASSERT_LT(n[i], static_cast<int64_t>(m.num_points())) << name;
      used[n[i]] = 1;
    }
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << name << ": unused points";
  for (std::size_t p = 0; p < m.num_points(); ++p) {
    ASSERT_TRUE(std::isfinite(m.values[p])) << name << " point " << p;
    for (double x : m.points[p])
      ASSERT_TRUE(std::isfinite(x)) << name << " point " << p;
  }
  EXPECT_FALSE(m.field_name.empty()) << name;
  EXPECT_EQ(m.source.rfind("generated:" + name + " seed=", 0), 0u) << m.source;
}

// The generators' random numbers are our own (splitmix64 and a 53-bit mapping to doubles), so a
// seed means the same dataset with any standard library. Pinned values: change them only on
// purpose (every dataset changes with them).
TEST(Datasets, SeededRandomIsPinned) {
  SeededRandom r(1, 0);
  EXPECT_EQ(r.next(), 0x810145e2f14b896dull);
  EXPECT_EQ(r.next(), 0x79e1e88840bb343bull);
  EXPECT_EQ(r.next(), 0x0e2fa2ad0fc46356ull);
  EXPECT_EQ(SeededRandom(1, 0).uniform(),
            static_cast<double>(0x810145e2f14b896dull >> 11) * 0x1.0p-53)
      << "uniform() takes the top 53 bits";
  SeededRandom a(7, 1), b(7, 2), c(8, 1);
  EXPECT_NE(a.next(), b.next()) << "streams must differ";
  EXPECT_NE(SeededRandom(7, 1).next(), c.next()) << "seeds must differ";
  double sum = 0, lo = 1, hi = 0;
  SeededRandom u(3);
  for (int i = 0; i < 100000; ++i) {
    const double x = u.uniform();
    sum += x;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LT(hi, 1.0);
  EXPECT_NEAR(sum / 100000, 0.5, 0.005);
}

TEST(Datasets, NamesAndDescriptions) {
  const std::vector<std::string> expected = {"conductor", "gauss",  "heater",      "plate",
                                             "random",    "sphere", "two-triangle"};
  EXPECT_EQ(dataset_names(), expected);
  for (const auto &n : dataset_names())
    EXPECT_FALSE(dataset_description(n).empty()) << n;
  EXPECT_TRUE(dataset_description("nope").empty());
  EXPECT_THROW(make("nope"), Error);
}

TEST(Datasets, DefaultSizesAndDegrees) {
  // The thesis' sizes (Table 5.1) and degrees; the mesh families allow "about" these.
  const std::map<std::string, std::pair<long long, int>> defaults = {
      {"conductor", {4298, 2}}, {"gauss", {722, 2}},    {"heater", {12438, 3}},
      {"plate", {20000, 3}},    {"random", {20000, 3}}, {"sphere", {1056, 3}},
      {"two-triangle", {2, 5}}};
  for (const auto &name : dataset_names()) {
    SCOPED_TRACE(name);
    const MeshInput m = make(name);
    const auto [target, degree] = defaults.at(name);
    EXPECT_NEAR(static_cast<double>(m.num_cells()), static_cast<double>(target), 0.08 * target);
    expect_well_formed(m, degree, name);
  }
}

TEST(Datasets, RequestedSizesAndDegrees) {
  for (const std::string name : {"gauss", "sphere", "heater", "conductor", "random"})
    for (long long target : {800LL, 2000LL, 5000LL}) {
      const MeshInput m = make(name, target);
      EXPECT_NEAR(static_cast<double>(m.num_cells()), static_cast<double>(target), 0.12 * target)
          << name << " --cells " << target;
    }
  for (int d = 1; d <= 10; ++d) {
    expect_well_formed(make("random", 200, d), d, "random");
    expect_well_formed(make("two-triangle", 0, d), d, "two-triangle");
  }
  expect_well_formed(make("sphere", 80, 6), 6, "sphere");
  expect_well_formed(make("heater", 600, 1), 1, "heater");
  EXPECT_NEAR(static_cast<double>(make("random", 200000, 1).num_cells()), 200000, 2000);
  EXPECT_THROW(make("random", 0, 11), Error);
  EXPECT_THROW(make("random", 0, -1), Error);
  EXPECT_THROW(make("random", -5), Error);
  EXPECT_THROW(make("sphere", 5), Error);
  EXPECT_THROW(make("two-triangle", 10), Error);
  EXPECT_THROW(make("random", 40000000, 10), Error); // too large to hold
  EXPECT_EQ(make("two-triangle", 2).num_cells(), 2u);
}

TEST(Datasets, DeterministicForASeed) {
  for (const auto &name : dataset_names()) {
    SCOPED_TRACE(name);
    const long long cells = small_cells(name);
    const MeshInput a = make(name, cells), b = make(name, cells), c = make(name, cells, 0, 2);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.cell_nodes, b.cell_nodes);
    EXPECT_EQ(a.source, b.source);
    EXPECT_NE(a.values, c.values) << "the seed does not change the field";
    EXPECT_NE(a.source, c.source);
    if (name == "gauss" || name == "conductor" || name == "random") {
      EXPECT_NE(a.points, c.points) << "the seed does not change the jitter";
    }
  }
}

// For every edge (pair of corners) used by two cells, both cells list the same interior node ids
// along it (reversed as needed) and run it in opposite directions (consistent orientation).
TEST(Datasets, SharedEdgesShareTheirNodes) {
  for (const auto &name : dataset_names()) {
    SCOPED_TRACE(name);
    for (int degree : {0, 4}) {
      const MeshInput m = make(name, small_cells(name), degree);
      struct Use {
        std::vector<int64_t> ids; // from the lower corner id to the higher
        bool forward;             // the cell runs the edge from lower to higher
        std::size_t cell;
      };
      std::map<std::pair<int64_t, int64_t>, std::vector<Use>> edges;
      for (std::size_t c = 0; c < m.num_cells(); ++c) {
        const int d = m.cell_degree[c];
        const int64_t *n = nodes_of(m, c);
        for (int k = 0; k < 3; ++k) {
          std::vector<int64_t> ids;
          for (int t = 0; t <= d; ++t)
            ids.push_back(n[edge_lattice_index(d, k, t)]);
          const bool forward = ids.front() < ids.back();
          if (!forward)
            std::reverse(ids.begin(), ids.end());
          edges[{ids.front(), ids.back()}].push_back({ids, forward, c});
        }
      }
      int64_t shared = 0, boundary = 0;
      for (const auto &[key, uses] : edges) {
        ASSERT_LE(uses.size(), 2u) << "non-manifold edge " << key.first << "-" << key.second;
        if (uses.size() == 1) {
          ++boundary;
          continue;
        }
        ++shared;
        EXPECT_EQ(uses[0].ids, uses[1].ids)
            << "cells " << uses[0].cell << " and " << uses[1].cell << " disagree on edge nodes";
        EXPECT_NE(uses[0].forward, uses[1].forward)
            << "cells " << uses[0].cell << " and " << uses[1].cell << " are oriented differently";
      }
      EXPECT_GT(shared, 0);
      if (is_planar(name))
        EXPECT_GT(boundary, 0);
      else
        EXPECT_EQ(boundary, 0) << "a closed surface has no boundary edges";
    }
  }
}

// No point is duplicated: distinct ids have distinct positions (a shared node created twice would
// leave the two cells disconnected even with equal coordinates).
TEST(Datasets, NoDuplicatePoints) {
  for (const auto &name : dataset_names()) {
    const MeshInput m = make(name, small_cells(name), 3);
    std::vector<Vec3> p(m.points.begin(), m.points.end());
    std::sort(p.begin(), p.end());
    for (std::size_t i = 1; i < p.size(); ++i)
      ASSERT_GT(norm(sub(p[i], p[i - 1])), 1e-9) << name << ": two points at the same position";
  }
}

// Euler characteristic V - E + F of the corner mesh and the number of boundary loops, computed
// here from the corner ids (independently of the library's topology).
std::pair<int64_t, int64_t> euler_and_loops(const MeshInput &m) {
  std::set<int64_t> vertices;
  std::map<std::pair<int64_t, int64_t>, int> edge_count;
  for (std::size_t c = 0; c < m.num_cells(); ++c) {
    const int d = m.cell_degree[c];
    const int64_t *n = nodes_of(m, c);
    const int64_t v[3] = {n[corner_index(d, 0)], n[corner_index(d, 1)], n[corner_index(d, 2)]};
    for (int k = 0; k < 3; ++k) {
      vertices.insert(v[k]);
      ++edge_count[{std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3])}];
    }
  }
  std::map<int64_t, std::vector<int64_t>> boundary_adjacency;
  for (const auto &[e, count] : edge_count)
    if (count == 1) {
      boundary_adjacency[e.first].push_back(e.second);
      boundary_adjacency[e.second].push_back(e.first);
    }
  int64_t loops = 0;
  std::set<int64_t> seen;
  for (const auto &[start, next] : boundary_adjacency) {
    if (seen.count(start))
      continue;
    ++loops;
    std::vector<int64_t> stack = {start};
    while (!stack.empty()) {
      const int64_t v = stack.back();
      stack.pop_back();
      if (!seen.insert(v).second)
        continue;
      for (int64_t w : boundary_adjacency[v])
        stack.push_back(w);
    }
  }
  const int64_t euler = static_cast<int64_t>(vertices.size()) -
                        static_cast<int64_t>(edge_count.size()) +
                        static_cast<int64_t>(m.num_cells());
  return {euler, loops};
}

TEST(Datasets, DomainsAreDisksOrSpheres) {
  for (const auto &name : dataset_names()) {
    const auto [euler, loops] = euler_and_loops(make(name, small_cells(name)));
    if (name == "plate") { // the one with holes: 100 of them
      EXPECT_EQ(euler, -99);
      EXPECT_EQ(loops, 101);
    } else if (is_planar(name)) {
      EXPECT_EQ(euler, 1) << name;
      EXPECT_EQ(loops, 1) << name;
    } else {
      EXPECT_EQ(euler, 2) << name;
      EXPECT_EQ(loops, 0) << name;
    }
  }
}

// Planar cells: z = 0, every lattice sub-triangle counter-clockwise with a positive area, and the
// cells well shaped (smallest angle of the corner triangle at least 20 degrees).
TEST(Datasets, PlanarCellsAreCounterClockwiseAndWellShaped) {
  for (const std::string name : {"gauss", "two-triangle", "conductor", "random"})
    for (int degree : {0, 3}) {
      SCOPED_TRACE(name);
      const MeshInput m = make(name, small_cells(name), degree);
      double smallest_angle = 180;
      for (std::size_t c = 0; c < m.num_cells(); ++c) {
        const int d = m.cell_degree[c];
        const int64_t *n = nodes_of(m, c);
        for (int i = 0; i < lattice_size(d); ++i)
          ASSERT_EQ(m.points[n[i]][2], 0.0);
        const Vec3 &p0 = m.points[n[corner_index(d, 0)]], &p1 = m.points[n[corner_index(d, 1)]],
                   &p2 = m.points[n[corner_index(d, 2)]];
        const double area = cross(sub(p1, p0), sub(p2, p0))[2] / 2;
        for (const auto &t : sub_triangles(d)) {
          const Vec3 &a = m.points[n[t[0]]], &b = m.points[n[t[1]]], &e = m.points[n[t[2]]];
          ASSERT_GT(cross(sub(b, a), sub(e, a))[2] / 2, 1e-3 * area / (d * d))
              << "cell " << c << " has a non-positive sub-triangle";
        }
        const Vec3 *p[3] = {&p0, &p1, &p2};
        for (int k = 0; k < 3; ++k) {
          const Vec3 u = sub(*p[(k + 1) % 3], *p[k]), v = sub(*p[(k + 2) % 3], *p[k]);
          smallest_angle = std::min(smallest_angle, std::acos(dot(u, v) / (norm(u) * norm(v))) *
                                                        180 / std::numbers::pi);
        }
      }
      EXPECT_GT(smallest_angle, 20.0);
    }
}

// Closed surfaces: no folds (every lattice sub-triangle's normal agrees with its cell's corner
// normal), outward (the enclosed volume, by the divergence theorem over the sub-triangles, is
// positive), and for the sphere every node exactly on the unit sphere, every sub-triangle facing
// outward, and the enclosed volume close to 4 pi / 3.
TEST(Datasets, SurfacesAreOutwardAndFoldFree) {
  for (const std::string name : {"sphere", "heater"}) {
    SCOPED_TRACE(name);
    const MeshInput m = make(name, name == "heater" ? 3000 : 0);
    double volume = 0;
    for (std::size_t c = 0; c < m.num_cells(); ++c) {
      const int d = m.cell_degree[c];
      const int64_t *n = nodes_of(m, c);
      const Vec3 &p0 = m.points[n[corner_index(d, 0)]], &p1 = m.points[n[corner_index(d, 1)]],
                 &p2 = m.points[n[corner_index(d, 2)]];
      const Vec3 corner_normal = cross(sub(p1, p0), sub(p2, p0));
      for (const auto &t : sub_triangles(d)) {
        const Vec3 &a = m.points[n[t[0]]], &b = m.points[n[t[1]]], &e = m.points[n[t[2]]];
        const Vec3 normal = cross(sub(b, a), sub(e, a));
        ASSERT_GT(dot(normal, corner_normal), 0) << "cell " << c << " folds";
        if (name == "sphere") {
          ASSERT_GT(dot(normal, a), 0) << "cell " << c << " faces inward";
        }
        volume += dot(a, cross(b, e)) / 6;
      }
    }
    if (name == "sphere") {
      for (const Vec3 &p : m.points)
        ASSERT_NEAR(norm(p), 1.0, 1e-12);
      EXPECT_NEAR(volume, 4 * std::numbers::pi / 3, 0.01 * 4 * std::numbers::pi / 3);
    } else {
      // The finned panel: 4 x 2 x 0.6 .. 0.96 as a box, less its rounded edges.
      EXPECT_GT(volume, 3.0);
      EXPECT_LT(volume, 4 * 2 * 0.96);
    }
  }
}

// The heater's nodes lie on its documented surface (heater.cpp): X = L u_x, Y = T(X) u_y,
// Z = H u_z with u on the unit superellipsoid u_x^4 + u_y^4 + u_z^4 = 1, so every node satisfies
// (X / L)^4 + (Y / T(X))^4 + (Z / H)^4 = 1, with full fins at the default size.
TEST(Datasets, HeaterNodesLieOnTheFinnedSurface) {
  const MeshInput m = make("heater");
  const double L = 2, H = 1, T0 = 0.3, F = 0.6, P = 0.5;
  double worst = 0, thickest = 0;
  for (const Vec3 &p : m.points) {
    const double c = 0.5 + 0.5 * std::cos(2 * std::numbers::pi * p[0] / P);
    const double T = T0 * (1 + F * c * c);
    const double s = std::pow(p[0] / L, 4) + std::pow(p[1] / T, 4) + std::pow(p[2] / H, 4);
    worst = std::max(worst, std::abs(s - 1));
    thickest = std::max(thickest, std::abs(p[1]));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(thickest, T0 * (1 + 0.9 * F)); // the fins are there
}

// Nodes are equispaced on straight planar cells: the edge and interior nodes of a planar cell are
// the lattice points of its corner triangle (so the cell's map is affine and exact polynomial
// fields stay exact).
TEST(Datasets, PlanarNodesAreEquispaced) {
  for (const std::string name : {"gauss", "two-triangle", "conductor", "random"}) {
    const MeshInput m = make(name, small_cells(name), 4);
    for (std::size_t c = 0; c < m.num_cells(); ++c) {
      const int d = m.cell_degree[c];
      const int64_t *n = nodes_of(m, c);
      const Vec3 &p0 = m.points[n[corner_index(d, 0)]], &p1 = m.points[n[corner_index(d, 1)]],
                 &p2 = m.points[n[corner_index(d, 2)]];
      for (int i = 0; i < lattice_size(d); ++i) {
        const auto ab = lattice_point(d, i);
        const double u = static_cast<double>(ab[0]) / d, v = static_cast<double>(ab[1]) / d;
        for (int k = 0; k < 2; ++k)
          ASSERT_NEAR(m.points[n[i]][k], (1 - u - v) * p0[k] + u * p1[k] + v * p2[k], 1e-12)
              << name << " cell " << c << " node " << i;
      }
    }
  }
}

// The monomial coefficients of the polynomial of total degree d (x^i y^j, i + j <= d) through a
// planar cell's nodes, by solving the Vandermonde system.
Eigen::VectorXd fit_monomials(const MeshInput &m, std::size_t c) {
  const int d = m.cell_degree[c];
  const int L = lattice_size(d);
  const int64_t *n = nodes_of(m, c);
  Eigen::MatrixXd V(L, L);
  Eigen::VectorXd f(L);
  for (int r = 0; r < L; ++r) {
    const Vec3 &p = m.points[n[r]];
    int col = 0;
    for (int i = 0; i <= d; ++i)
      for (int j = 0; i + j <= d; ++j)
        V(r, col++) = std::pow(p[0], i) * std::pow(p[1], j);
    f(r) = m.values[n[r]];
  }
  return V.colPivHouseholderQr().solve(f);
}

TEST(Datasets, ConductorHasPlateausRidgesAndOrdinaryCells) {
  const MeshInput m = make("conductor");
  int64_t constant = 0, ridge = 0, valley = 0, ordinary = 0;
  for (std::size_t c = 0; c < m.num_cells(); ++c) {
    const int64_t *n = nodes_of(m, c);
    const int L = lattice_size(m.cell_degree[c]);
    ASSERT_EQ(m.cell_degree[c], 2);
    bool all_equal = true;
    for (int i = 1; i < L; ++i)
      all_equal = all_equal && m.values[n[i]] == m.values[n[0]];
    if (all_equal) {
      ++constant;
      continue;
    }
    // f = a0 + b.x + x^T H x / 2. A ridge or valley cell: H of rank 1 (null vector w), the gradient
    // b + H x vanishing on a line (b in the range of H: b . w = 0) that crosses the cell; a ridge
    // if the non-zero eigenvalue is negative.
    const Eigen::VectorXd q = fit_monomials(m, c); // 1, y, y^2, x, xy, x^2
    const double bx = q(3), by = q(1);
    Eigen::Matrix2d H;
    H << 2 * q(5), q(4), q(4), 2 * q(2);
    const double scale = H.norm();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(H);
    const double small = std::abs(eig.eigenvalues()(0)) < std::abs(eig.eigenvalues()(1))
                             ? eig.eigenvalues()(0)
                             : eig.eigenvalues()(1);
    if (scale < 1e-6 || std::abs(small) > 1e-9 * scale) {
      ++ordinary;
      continue;
    }
    const int big = std::abs(eig.eigenvalues()(0)) > std::abs(eig.eigenvalues()(1)) ? 0 : 1;
    const Eigen::Vector2d w = eig.eigenvectors().col(1 - big), nrm = eig.eigenvectors().col(big);
    if (std::abs(bx * w(0) + by * w(1)) > 1e-8 * (std::abs(bx) + std::abs(by) + 1))
      continue; // a parabolic cylinder without critical points
    // Critical line: nrm . x = t with lambda t + nrm . b = 0.
    const double t = -(bx * nrm(0) + by * nrm(1)) / eig.eigenvalues()(big);
    int below = 0, above = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 &p = m.points[n[corner_index(2, k)]];
      (p[0] * nrm(0) + p[1] * nrm(1) < t ? below : above) += 1;
    }
    if (below > 0 && above > 0)
      ++(eig.eigenvalues()(big) < 0 ? ridge : valley);
  }
  EXPECT_GE(constant, 10);
  // The legs' ridges (maxima along a segment). Valleys appear too: quadratic cells with five
  // nodes on the plateau and one off it hold 0.3 + lambda l (l - h/2), whose floor crosses them.
  EXPECT_GE(ridge, 10);
  EXPECT_GT(ordinary, static_cast<int64_t>(m.num_cells()) / 2);
}

// Gradient (g) and Hessian (h: xx, xy, yy) of sum q_ij x^i y^j, i + j <= 5, with the
// coefficients in fit_monomials' order (i outer, j inner).
void quintic_derivatives(const Eigen::VectorXd &q, double x, double y, double g[2], double h[3]) {
  auto pw = [](double b, int e) { return e < 0 ? 0.0 : std::pow(b, e); };
  g[0] = g[1] = h[0] = h[1] = h[2] = 0;
  int col = 0;
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; i + j <= 5; ++j, ++col) {
      const double a = q(col);
      g[0] += a * i * pw(x, i - 1) * pw(y, j);
      g[1] += a * j * pw(x, i) * pw(y, j - 1);
      h[0] += a * i * (i - 1) * pw(x, i - 2) * pw(y, j);
      h[1] += a * i * j * pw(x, i - 1) * pw(y, j - 1);
      h[2] += a * j * (j - 1) * pw(x, i) * pw(y, j - 2);
    }
}

// Critical points of the quintic in the open unit square: Newton's method from a 41 x 41 grid of
// starts, converged points deduplicated.
std::vector<std::array<double, 2>> quintic_critical_points(const Eigen::VectorXd &q) {
  std::vector<std::array<double, 2>> found;
  for (int si = 0; si <= 40; ++si)
    for (int sj = 0; sj <= 40; ++sj) {
      double x = si / 40.0, y = sj / 40.0;
      bool converged = false;
      for (int it = 0; it < 60 && !converged; ++it) {
        double g[2], h[3];
        quintic_derivatives(q, x, y, g, h);
        const double det = h[0] * h[2] - h[1] * h[1];
        if (det == 0)
          break;
        const double dx = (h[2] * g[0] - h[1] * g[1]) / det, dy = (h[0] * g[1] - h[1] * g[0]) / det;
        x -= dx;
        y -= dy;
        converged = std::abs(dx) + std::abs(dy) < 1e-14;
        if (std::abs(x) > 3 || std::abs(y) > 3)
          break;
      }
      if (!converged || x <= 0 || x >= 1 || y <= 0 || y >= 1)
        continue;
      const bool fresh = std::none_of(found.begin(), found.end(), [&](const auto &p) {
        return std::abs(p[0] - x) + std::abs(p[1] - y) < 1e-7;
      });
      if (fresh)
        found.push_back({x, y});
    }
  return found;
}

// The two-triangle quintic, recovered from each cell's 21 nodes: both cells hold the same global
// polynomial, and Newton's method finds 16 non-degenerate critical points in the open square, 11
// in cell 0 (below the diagonal), 5 in cell 1, none near the diagonal, for several seeds.
TEST(Datasets, TwoTriangleQuinticHasElevenCriticalPointsInOneCell) {
  for (uint64_t seed : {1, 2, 3, 7, 12345}) {
    SCOPED_TRACE(seed);
    const MeshInput m = make("two-triangle", 0, 0, seed);
    ASSERT_EQ(m.num_cells(), 2u);
    const Eigen::VectorXd q0 = fit_monomials(m, 0), q1 = fit_monomials(m, 1);
    EXPECT_LT((q0 - q1).cwiseAbs().maxCoeff(), 1e-8) << "the cells hold different polynomials";
    // Cell 0 is the triangle below the diagonal.
    const int64_t *n0 = nodes_of(m, 0);
    for (int k = 0; k < 3; ++k)
      EXPECT_GE(m.points[n0[corner_index(5, k)]][0], m.points[n0[corner_index(5, k)]][1]);
    const auto found = quintic_critical_points(q0);
    int below = 0, above = 0, near_diagonal = 0;
    for (const auto &p : found) {
      double g[2], h[3];
      quintic_derivatives(q0, p[0], p[1], g, h);
      EXPECT_GT(std::abs(h[0] * h[2] - h[1] * h[1]), 1e-3) << "degenerate critical point";
      (p[1] < p[0] ? below : above) += 1;
      near_diagonal += std::abs(p[0] - p[1]) < 0.02;
    }
    EXPECT_EQ(found.size(), 16u);
    EXPECT_EQ(below, 11);
    EXPECT_EQ(above, 5);
    EXPECT_EQ(near_diagonal, 0);
  }
}

// What the datasets are for, end to end: the exact tree of the two-triangle toy has its 16
// interior critical points (found above by Newton's method) as interior nodes in the right
// cells, and the conductor's plateau and ridge cells take the library's degenerate-cell path.
TEST(Datasets, ExactTreeSeesTheDesignedFeatures) {
  const MeshInput two = make("two-triangle");
  const auto expected = quintic_critical_points(fit_monomials(two, 0));
  ASSERT_EQ(expected.size(), 16u);
  const TreeResult t = exact_contour_tree(build_mesh(two));
  for (const auto &p : expected) {
    int hits = 0;
    for (const auto &n : t.nodes)
      if (n.location == NodeLocation::Interior && std::abs(n.position[0] - p[0]) < 1e-8 &&
          std::abs(n.position[1] - p[1]) < 1e-8) {
        ++hits;
        EXPECT_EQ(n.cell, p[1] < p[0] ? 0 : 1);
      }
    EXPECT_EQ(hits, 1) << "critical point (" << p[0] << ", " << p[1] << ")";
  }
  const TreeResult c = exact_contour_tree(build_mesh(make("conductor", 1200)));
  double fallbacks = 0;
  for (const auto &[k, v] : c.stats.entries())
    if (k == "fallback_cells")
      fallbacks = v;
  EXPECT_GT(fallbacks, 0);
  EXPECT_EQ(c.arcs.size() + 1, c.nodes.size());
}

// --frequency F multiplies the random field's wave numbers: on F^2 times the cells (the same
// cells per feature) its exact tree has about F^2 times the nodes; F = 1 is the default field.
TEST(Datasets, RandomFrequencyScalesTheFeatures) {
  DatasetOptions o;
  o.cells = 5000;
  const MeshInput base = generate_dataset("random", o);
  o.frequency = 1;
  EXPECT_EQ(generate_dataset("random", o).values, base.values);
  o.frequency = 2;
  o.cells = 20000;
  const MeshInput dense = generate_dataset("random", o);
  EXPECT_NE(dense.source.find("frequency=2"), std::string::npos) << dense.source;
  const double n1 = static_cast<double>(exact_contour_tree(build_mesh(base)).nodes.size());
  const double n2 = static_cast<double>(exact_contour_tree(build_mesh(dense)).nodes.size());
  EXPECT_GT(n2, 2.5 * n1) << n1 << " -> " << n2;
  EXPECT_LT(n2, 6.0 * n1) << n1 << " -> " << n2;
  for (double bad : {0.0, -1.0, 2000.0, std::nan("")}) {
    o.frequency = bad;
    EXPECT_THROW(generate_dataset("random", o), Error) << bad;
  }
  o.frequency = 2;
  o.cells = 0;
  EXPECT_THROW(generate_dataset("gauss", o), Error);
}

// --plateau P raises the random field's values below their P-th percentile to it: the other
// values are untouched, about P% of them sit on the plateau, cells with every node on it are
// constant (the exact tree's constant-cell fallback), and the plateau is the tree's lowest value.
TEST(Datasets, RandomPlateauRaisesTheLowestValues) {
  DatasetOptions o;
  o.cells = 5000;
  const MeshInput base = generate_dataset("random", o);
  o.plateau = 30;
  const MeshInput flat = generate_dataset("random", o);
  EXPECT_NE(flat.source.find("plateau=30"), std::string::npos) << flat.source;
  ASSERT_EQ(flat.values.size(), base.values.size());
  const double level = *std::min_element(flat.values.begin(), flat.values.end());
  std::size_t on = 0, below = 0;
  for (std::size_t i = 0; i < base.values.size(); ++i) {
    below += base.values[i] < level;
    if (base.values[i] >= level)
      EXPECT_EQ(flat.values[i], base.values[i]) << i;
    else
      EXPECT_EQ(flat.values[i], level) << i;
    on += flat.values[i] == level;
  }
  const double n = static_cast<double>(base.values.size());
  EXPECT_NEAR(static_cast<double>(below) / n, 0.30, 0.001);
  EXPECT_GE(on, below);
  const Mesh mesh = build_mesh(flat);
  const TreeResult tree = exact_contour_tree(mesh);
  const auto entries = tree.stats.entries();
  std::map<std::string, double> stats(entries.begin(), entries.end());
  EXPECT_GT(stats["fallback_constant_cell"], 0.1 * static_cast<double>(mesh.topology.num_cells()));
  // Every constant cell has constant edges where the gradient vanishes (no level edge for it):
  // a degenerate edge too. The cells around the plateau with a constant edge the field rises
  // across (a level edge) are searched as any other.
  EXPECT_GE(stats["fallback_degenerate_edge"], stats["fallback_constant_cell"]);
  EXPECT_GT(stats["level_edges"], 0);
  EXPECT_LE(tree.nodes.front().value, level); // interpolation may dip below the plateau
  for (double bad : {-1.0, 100.0, std::nan("")}) {
    o.plateau = bad;
    EXPECT_THROW(generate_dataset("random", o), Error) << bad;
  }
  o.plateau = 10;
  o.cells = 0;
  EXPECT_THROW(generate_dataset("gauss", o), Error);
}

TEST(Datasets, GaussDiskBoundaryStaysOnTheCircle) {
  const MeshInput m = make("gauss");
  std::map<std::pair<int64_t, int64_t>, int> count;
  for (std::size_t c = 0; c < m.num_cells(); ++c) {
    const int64_t *n = nodes_of(m, c);
    const int64_t v[3] = {n[corner_index(2, 0)], n[corner_index(2, 1)], n[corner_index(2, 2)]};
    for (int k = 0; k < 3; ++k)
      ++count[{std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3])}];
  }
  std::set<int64_t> boundary;
  for (const auto &[e, k] : count)
    if (k == 1) {
      boundary.insert(e.first);
      boundary.insert(e.second);
    }
  ASSERT_GE(boundary.size(), 6u);
  for (int64_t v : boundary)
    EXPECT_NEAR(norm(m.points[v]), 1.0, 1e-12) << "boundary vertex " << v;
  double inner = 0;
  for (const auto &[e, k] : count)
    for (int64_t v : {e.first, e.second})
      if (!boundary.count(v))
        inner = std::max(inner, norm(m.points[v]));
  EXPECT_LT(inner, 1.0);
}

// The library's checks (input structure, Jacobians of planar cells in Bernstein form, normals of
// curved cells not flipping) accept every dataset, at coarse and fine sizes and several degrees:
// coarse curved cells are where folds would appear.
TEST(Datasets, LibraryAcceptsEveryDataset) {
  struct Case {
    std::string name;
    std::vector<long long> cells;
  };
  const std::vector<Case> cases = {
      {"gauss", {6, 100, 0}},      {"sphere", {20, 80, 500, 0}},
      {"two-triangle", {0}},       {"heater", {600, 1000, 2000, 4000, 0}},
      {"conductor", {14, 300, 0}}, {"random", {2, 500, 0}}};
  for (const auto &c : cases)
    for (long long cells : c.cells)
      for (int degree : {0, 1, 2, 3, 5}) {
        const MeshInput m = make(c.name, cells, degree);
        const Mesh mesh = build_mesh(m, {.throw_on_error = false});
        EXPECT_TRUE(mesh.complete && !mesh.problems.has_errors())
            << c.name << " --cells " << cells << " --degree " << degree << "\n"
            << mesh.problems.summary();
      }
}

} // namespace
} // namespace hoct
