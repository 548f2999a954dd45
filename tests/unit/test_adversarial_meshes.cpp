// Adversarial meshes for resource safety (issue 8): one vertex shared by 100,000 cells, thousands
// of critical points along one line, clusters of near-coincident critical points, degree-15
// cells. Each must give a valid tree (checked against independent truth where there is one) in
// near-linear time: the timings of two sizes are compared, a quadratic algorithm would show a
// ratio near the square of the size ratio.
#include "exact/exact_contour_tree.hpp"
#include "fuzz_harness.hpp"
#include "mesh/mesh.hpp"
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

namespace hoct {
namespace {

struct Timed {
  TreeResult tree;
  double seconds = 0;
};

Timed build_and_tree(const MeshInput &in) {
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh mesh = build_mesh(in);
  Timed r{exact_contour_tree(mesh), 0};
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

// A disk fanned around the origin: n triangles all sharing vertex 0.
MeshInput fan(int n, int degree, const std::function<double(const Vec3 &)> &f) {
  std::vector<Vec3> v{{0, 0, 0}};
  std::vector<std::array<int64_t, 3>> t;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    v.push_back({std::cos(a), std::sin(a), 0});
    t.push_back({0, 1 + k, 1 + (k + 1) % n});
  }
  std::mt19937_64 rng(1);
  return testing::lagrange_mesh(
      v, t, [=](int64_t) { return degree; }, nullptr, f, rng, false);
}

// The strip [0, w] x [0, 1] in nx x 1 squares split in two.
MeshInput strip(int nx, double w, int degree, const std::function<double(const Vec3 &)> &f) {
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= nx; ++i)
      v.push_back({w * i / nx, static_cast<double>(j), 0});
  for (int i = 0; i < nx; ++i) {
    const int64_t a = i, b = i + 1, c = nx + 2 + i, d = nx + 1 + i;
    t.push_back({a, b, c});
    t.push_back({a, c, d});
  }
  std::mt19937_64 rng(1);
  return testing::lagrange_mesh(
      v, t, [=](int64_t) { return degree; }, nullptr, f, rng, false);
}

int64_t count(const TreeResult &t, NodeType type) {
  int64_t n = 0;
  for (const auto &node : t.nodes)
    n += node.type == type;
  return n;
}

// A linear field on a fan: the reduced tree is one arc from the lowest to the highest ring
// vertex, whatever the number of cells around the centre.
TEST(AdversarialMeshes, VertexSharedBy100000Cells) {
  const auto f = [](const Vec3 &p) { return p[0] + 0.3 * p[1]; };
  const Timed small = build_and_tree(fan(10000, 1, f));
  const Timed big = build_and_tree(fan(100000, 1, f));
  for (const Timed *r : {&small, &big}) {
    EXPECT_EQ(fuzz::tree_invariant_violation(r->tree), "");
    ASSERT_EQ(r->tree.nodes.size(), 2u);
    // Extremes of x + 0.3 y on the unit circle: -+sqrt(1.09), up to the polygon's chord error.
    EXPECT_NEAR(r->tree.nodes[0].value, -std::sqrt(1.09), 1e-6);
    EXPECT_NEAR(r->tree.nodes[1].value, std::sqrt(1.09), 1e-6);
  }
  std::printf("fan: 10000 cells %.3f s, 100000 cells %.3f s\n", small.seconds, big.seconds);
  EXPECT_LT(big.seconds, 30 * small.seconds + 0.5); // 10x the cells; quadratic would be ~100x
}

// The same fan at degree 2 with a quadratic field (represented exactly): one minimum inside, at
// (-1/4, -1/16), among 20,000 cells 3e-4 rad wide; on the boundary polygon two maxima (near
// y = 1 and y = -1) and a saddle between them, plus pairs of persistence ~1e-8 where the
// polygon's chords wiggle around the circle's boundary extrema (real for this mesh). In these
// thin cells the reference normal of an edge is nearly tangent in the plane: the lower sector of
// an edge minimum near the true minimum dips ~1e-15 along it, below the certification margin, and
// those cells fell back to the PL rule (31 spurious minima within 1e-5, found by this test). The
// sector is now entered along the Hessian-conjugate direction: every cell certifies.
double stat(const TreeResult &t, const std::string &name) {
  for (const auto &[k, v] : t.stats.entries())
    if (k == name)
      return v;
  ADD_FAILURE() << "no statistic " << name;
  return -1;
}

TEST(AdversarialMeshes, QuadraticFieldOn20000CellFan) {
  const Timed r = build_and_tree(fan(20000, 2, [](const Vec3 &p) {
    return p[0] * p[0] + 2 * p[1] * p[1] + 0.5 * p[0] + 0.25 * p[1];
  }));
  EXPECT_EQ(fuzz::tree_invariant_violation(r.tree), "");
  EXPECT_EQ(stat(r.tree, "fallback_certification_failed"), 0);
  EXPECT_EQ(stat(r.tree, "connections_failed"), 0);
  for (const auto &node : r.tree.nodes)
    EXPECT_FALSE(node.fallback);
  const double exact_min = -0.0625 - 0.0078125;
  ASSERT_EQ(count(r.tree, NodeType::Minimum), 1);
  EXPECT_NEAR(r.tree.nodes.front().value, exact_min, 1e-12);
  EXPECT_NEAR(r.tree.nodes.front().position[0], -0.25, 1e-6);
  EXPECT_NEAR(r.tree.nodes.front().position[1], -0.0625, 1e-6);
  const TreeResult simple = simplify_tree(r.tree, 1e-4);
  EXPECT_EQ(count(simple, NodeType::Minimum), 1);
  EXPECT_EQ(count(simple, NodeType::Maximum), 2);
  EXPECT_EQ(count(simple, NodeType::Saddle), 1);
  std::printf("quadratic fan: 20000 cells %.3f s, %zu nodes before simplification\n", r.seconds,
              r.tree.nodes.size());
}

// cos(2 pi (k x - 1/8)) + 0.5 y on a strip, interpolated at degree 4 with 4 columns per period
// (the extrema of cos fall inside columns, where the interpolant is smooth). The field is
// Q(x) + 0.5 y, so all critical points lie on the boundary, thousands along one line of edges:
// a minimum per period on y = 0 and a maximum on y = 1, a saddle on each edge between them, plus
// the corners (0, 0) (a minimum) and (1, 1) (a maximum).
TEST(AdversarialMeshes, ThousandsOfCriticalPointsAlongOneLine) {
  auto run = [](int periods) {
    const auto f = [=](const Vec3 &p) {
      return std::cos(2 * std::numbers::pi * (periods * p[0] - 0.125)) + 0.5 * p[1];
    };
    return build_and_tree(strip(4 * periods, 1.0, 4, f));
  };
  const Timed small = run(200), big = run(2000);
  for (const auto &[r, periods] : {std::pair{&small, 200}, std::pair{&big, 2000}}) {
    EXPECT_EQ(fuzz::tree_invariant_violation(r->tree), "");
    EXPECT_EQ(count(r->tree, NodeType::Minimum), periods + 1);
    EXPECT_EQ(count(r->tree, NodeType::Maximum), periods + 1);
    EXPECT_EQ(count(r->tree, NodeType::Saddle), 2 * periods);
    EXPECT_NEAR(r->tree.nodes.front().value, -1.0, 1e-4);
    EXPECT_NEAR(r->tree.nodes.back().value, 1.5, 1e-4);
  }
  std::printf("critical points along a line: %zu nodes %.3f s, %zu nodes %.3f s\n",
              small.tree.nodes.size(), small.seconds, big.tree.nodes.size(), big.seconds);
  EXPECT_LT(big.seconds, 30 * small.seconds + 0.5);
}

// Pairs of minima 2e-7 apart separated by a saddle 1e-26 higher (below double resolution of the
// values): ((x - c)^2 - delta^2)^2 per period. The tree must stay a valid tree; each pair is
// either resolved (two minima and a saddle) or merged into one minimum, never broken.
TEST(AdversarialMeshes, ClustersOfNearlyCoincidentCriticalPoints) {
  const int periods = 500;
  const double delta = 1e-7;
  const auto f = [=](const Vec3 &p) {
    const double x = p[0] * periods, c = std::floor(x) + 0.5, q = (x - c) * (x - c) - delta * delta;
    return q * q + 0.1 * p[1] + 1e-3 * p[0];
  };
  const Timed r = build_and_tree(strip(periods, 1.0, 4, f));
  EXPECT_EQ(fuzz::tree_invariant_violation(r.tree), "");
  const int64_t minima = count(r.tree, NodeType::Minimum);
  EXPECT_GE(minima, periods);
  EXPECT_LE(minima, 2 * periods);
  std::printf("near-coincident clusters: %lld minima, %zu nodes, %.3f s\n",
              static_cast<long long>(minima), r.tree.nodes.size(), r.seconds);
}

// Degree 15 (the readers accept up to 20 in VTU, 10 in MSH): a quartic with two minima, a saddle
// and boundary maxima represented at degree 4 and, exactly the same polynomial, at degree 15.
// Both exact trees must agree.
TEST(AdversarialMeshes, Degree15CellsGiveTheSameTreeAsDegree4) {
  const auto f = [](const Vec3 &p) {
    const double g = (p[0] - 0.5) * (p[0] - 0.5) - 0.04;
    return g * g + (p[1] - 0.5) * (p[1] - 0.5) + 0.01 * p[0] + 0.02 * p[1];
  };
  std::mt19937_64 rng(5);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(3, rng, v, t);
  auto tree_at = [&](int degree) {
    std::mt19937_64 r(7);
    return build_and_tree(testing::lagrange_mesh(
        v, t, [=](int64_t) { return degree; }, nullptr, f, r));
  };
  const Timed p4 = tree_at(4), p15 = tree_at(15);
  EXPECT_EQ(fuzz::tree_invariant_violation(p15.tree), "");
  ASSERT_EQ(p4.tree.nodes.size(), p15.tree.nodes.size());
  for (std::size_t i = 0; i < p4.tree.nodes.size(); ++i) {
    EXPECT_EQ(p4.tree.nodes[i].type, p15.tree.nodes[i].type) << i;
    EXPECT_NEAR(p4.tree.nodes[i].value, p15.tree.nodes[i].value, 1e-8) << i;
  }
  EXPECT_EQ(count(p15.tree, NodeType::Minimum), 2);
}

// Slivers of aspect ratio 20,000 (a strip of 2 x 20,000 triangles 5e-5 wide and 1 tall) carrying
// a cubic represented exactly at degrees 3 to 5: X^3 - 0.03 X + Y^2 (0.5 + X) + 0.00371 Y with
// X = x - 1/2, Y = y - 1/2 has exactly two critical points, a minimum and a saddle near
// X = +-0.1 (solved here by Newton from those starts). In the reference triangle of such a cell
// the two gradient components are nearly parallel and the Hessian's condition number is ~1e9:
// before preconditioning the exclusion test by the inverse Hessian and enclosing Y J(X) as one
// polynomial per entry in the Krawczyk test, hundreds of these cells reported a critical curve
// and fell back to the PL rule. Now every cell certifies and the interior nodes are exactly the
// analytic critical points.
constexpr int kSliverColumns = 20000;
TEST(AdversarialMeshes, SliverCellsCertifyTheirCriticalPoints) {
  const auto f = [](const Vec3 &p) {
    const double X = p[0] - 0.5, Y = p[1] - 0.5;
    return X * X * X - 0.03 * X + Y * Y * (0.5 + X) + 0.00371 * Y;
  };
  struct Crit {
    double x, y, value;
    NodeType type;
  };
  std::vector<Crit> truth;
  for (double x0 : {0.1, -0.1}) {
    double X = x0, Y = 0;
    for (int it = 0; it < 50; ++it) {
      const double fx = 3 * X * X - 0.03 + Y * Y, fy = 2 * Y * (0.5 + X) + 0.00371;
      const double a = 6 * X, b = 2 * Y, c = 2 * (0.5 + X), det = a * c - b * b;
      X -= (c * fx - b * fy) / det;
      Y -= (a * fy - b * fx) / det;
    }
    truth.push_back({X + 0.5, Y + 0.5, f({X + 0.5, Y + 0.5, 0}),
                     x0 > 0 ? NodeType::Minimum : NodeType::Saddle});
  }
  for (int degree : {3, 4, 5}) {
    const Timed r = build_and_tree(strip(kSliverColumns, 1.0, degree, f));
    EXPECT_EQ(fuzz::tree_invariant_violation(r.tree), "") << degree;
    EXPECT_EQ(stat(r.tree, "fallback_cells"), 0) << degree;
    std::vector<const TreeNode *> inside;
    for (const auto &node : r.tree.nodes)
      if (node.position[0] > 1e-3 && node.position[0] < 1 - 1e-3 && node.position[1] > 1e-3 &&
          node.position[1] < 1 - 1e-3)
        inside.push_back(&node);
    ASSERT_EQ(inside.size(), truth.size()) << degree;
    for (const Crit &c : truth) {
      const TreeNode *best = inside[0];
      for (const TreeNode *n : inside)
        if (std::hypot(n->position[0] - c.x, n->position[1] - c.y) <
            std::hypot(best->position[0] - c.x, best->position[1] - c.y))
          best = n;
      EXPECT_NEAR(best->position[0], c.x, 1e-7) << degree;
      EXPECT_NEAR(best->position[1], c.y, 1e-7) << degree;
      EXPECT_NEAR(best->value, c.value, 1e-12) << degree;
      EXPECT_EQ(best->type, c.type) << degree;
    }
    std::printf("slivers, degree %d: %zu nodes, %.3f s\n", degree, r.tree.nodes.size(), r.seconds);
  }
}

// A smooth non-polynomial field interpolated on the 20,000-cell fan (cells 3e-4 rad wide): no
// independent tree to compare with, but every cell must certify (before the fixes above, 13 to
// 136 cells per degree fell back and added PL nodes) and the tree must pass the checker.
TEST(AdversarialMeshes, SmoothFieldOnThinFanCellsNeedsNoFallback) {
  const auto f = [](const Vec3 &p) {
    return std::sin(3 * p[0] + 0.2) * std::cos(4 * p[1] - 0.3) + 0.1 * p[0];
  };
  for (int degree : {3, 4, 5}) {
    const Timed r = build_and_tree(fan(20000, degree, f));
    EXPECT_EQ(fuzz::tree_invariant_violation(r.tree), "") << degree;
    EXPECT_EQ(stat(r.tree, "fallback_cells"), 0) << degree;
    EXPECT_EQ(stat(r.tree, "connections_failed"), 0) << degree;
  }
}

} // namespace
} // namespace hoct
