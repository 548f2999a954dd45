// Degenerate isolated critical points (singular Hessian), classified by their sectors
// (cell/degenerate_points.hpp) instead of falling back: fields exactly representable in the
// cells' degree whose critical point and sectors are known in closed form. Independent truth: the
// hand-derived tree shapes, the field's value at the critical point (0), the checker (node values
// and positions against the field, types against samples around each node), and the PL trees of
// refinements converging to the exact tree.
#include "analysis/tree_check.hpp"
#include "cell/degenerate_points.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"
#include "poly/lattice.hpp"
#include "test_meshes.hpp"
#include "test_refinement_convergence.hpp"
#include "test_tree_shape.hpp"
#include "tree/persistence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace hoct {
namespace {

using Field2 = std::function<double(double, double)>;

// Coordinates rotated by 0.5 rad about the critical point (0.47, 0.52): no mesh edge is parallel
// to a sector's axis, so the edges' own critical points stay regular.
double U(double x, double y) { return std::cos(0.5) * (x - 0.47) + std::sin(0.5) * (y - 0.52); }
double W(double x, double y) { return -std::sin(0.5) * (x - 0.47) + std::cos(0.5) * (y - 0.52); }

const Field2 kMonkey = [](double x, double y) {
  const double u = U(x, y), w = W(x, y);
  return u * u * u - 3 * u * w * w; // three valleys, three ridges
};
const Field2 kFlatMinimum = [](double x, double y) {
  const double u = U(x, y), w = W(x, y);
  return u * u * u * u + w * w * w * w;
};
const Field2 kFlatMaximum = [](double x, double y) {
  const double u = U(x, y), w = W(x, y);
  return -(u * u * u * u + 2 * w * w * w * w);
};
const Field2 kInflection = [](double x, double y) {
  const double u = U(x, y), w = W(x, y);
  return u * u * u + w * w; // neither an extremum nor a saddle
};
const Field2 kFourLines = [](double x, double y) {
  const double u = U(x, y), w = W(x, y);
  return u * w * (u * u - w * w); // zero on four lines through the point: eight sectors
};
const Field2 kCusp = [](double x, double y) {
  const double u = U(x, y), w = W(x, y);
  return u * u * u * u - w * w; // its upper sectors |w| < u^2 are cusps
};

MeshInput on_grid(int degree, const Field2 &f, uint64_t seed = 3, bool jitter = true) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(6, rng, v, t);
  if (!jitter) // the lattice itself: (0.5, 0.5) is a vertex, x = 0.5 and y = 0.5 lines of edges
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; j <= 6; ++j)
        v[static_cast<std::size_t>(i * 7 + j)] = {j / 6.0, i / 6.0, 0};
  return testing::lagrange_mesh(
      v, t, [degree](int64_t) { return degree; }, nullptr,
      [&f](const Vec3 &p) { return f(p[0], p[1]); }, rng);
}

struct Computed {
  MeshInput input;
  Mesh mesh;
  TreeResult tree;
};

Computed computed(int degree, const Field2 &f, bool jitter = true) {
  Computed c{on_grid(degree, f, 3, jitter), {}, {}};
  c.mesh = build_mesh(c.input);
  c.tree = compute_tree(c.mesh, TreeRequest{}, &c.input).tree;
  return c;
}

// "type(down,up)" per node, ascending.
std::string shape(const TreeResult &t) { return testing::tree_shape(t); }

// The node at the critical point (0.47, 0.52), or null.
const TreeNode *node_at_the_point(const TreeResult &t, double tolerance, double x = 0.47,
                                  double y = 0.52) {
  for (const auto &n : t.nodes)
    if (std::hypot(n.position[0] - x, n.position[1] - y) <= tolerance)
      return &n;
  return nullptr;
}

// The common checks: no fallback, one point classified, the checker passes, and the PL trees of
// refinements converge to the exact tree.
void expect_certified(const Computed &c, int64_t classified) {
  const TreeResult &t = c.tree;
  ASSERT_TRUE(t.stats.exact);
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
  if (classified >= 0) {
    EXPECT_EQ(t.stats.exact->degenerate_points, classified);
  }
  EXPECT_GT(t.stats.exact->degenerate_slack, 0);
  EXPECT_LT(t.stats.exact->degenerate_slack, 1e-8);
  const TreeCheckReport report = check_tree(t, c.mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  testing::expect_refinements_converge(c.mesh, c.input, t);
}

TEST(DegeneratePoints, AMonkeySaddleIsOneSaddleWithThreeSectorsEachWay) {
  // u^3 - 3 u w^2 (P3): one node at 0 with three lower and three upper sectors, each reaching
  // the boundary at its lowest (highest) corner or edge point.
  const Computed c = computed(3, kMonkey);
  EXPECT_EQ(shape(c.tree), "minimum(0,1) minimum(0,1) minimum(0,1) saddle(3,3) maximum(1,0) "
                           "maximum(1,0) maximum(1,0)");
  const TreeNode *n = node_at_the_point(c.tree, 1e-6);
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->type, NodeType::Saddle);
  EXPECT_NEAR(n->value, 0, 1e-12);
  EXPECT_FALSE(n->fallback);
  expect_certified(c, 1);
}

TEST(DegeneratePoints, FlatExtremaAreExactNodes) {
  // u^4 + w^4 and -(u^4 + 2 w^4) (P4): the minimum (maximum) 0 at the point, where the
  // Hessian vanishes; before, a fallback cell's stand-in put it at one of its lattice nodes.
  for (bool minimum : {true, false}) {
    SCOPED_TRACE(minimum ? "minimum" : "maximum");
    const Computed c = computed(4, minimum ? kFlatMinimum : kFlatMaximum);
    // Fourth order: the field is within rounding of 0 up to about 1e-4 from the point, and the
    // node is somewhere there.
    const TreeNode *n = node_at_the_point(c.tree, 1e-4);
    ASSERT_NE(n, nullptr);
    EXPECT_EQ(n->type, minimum ? NodeType::Minimum : NodeType::Maximum);
    EXPECT_NEAR(n->value, 0, 1e-12);
    EXPECT_EQ(minimum ? c.tree.nodes.front().value : c.tree.nodes.back().value, n->value);
    expect_certified(c, 1);
  }
}

TEST(DegeneratePoints, AnInflectionIsNoNode) {
  // u^3 + w^2 (P4): one lower and one upper sector, a regular point: classified, no node.
  const Computed c = computed(4, kInflection);
  EXPECT_EQ(node_at_the_point(c.tree, 1e-2), nullptr);
  expect_certified(c, 1);
}

TEST(DegeneratePoints, FourLinesThroughAPointAreOneSaddleWithFourSectorsEachWay) {
  const Computed c = computed(4, kFourLines);
  const TreeNode *n = node_at_the_point(c.tree, 1e-4);
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->type, NodeType::Saddle);
  EXPECT_EQ(n->down, 4);
  EXPECT_EQ(n->up, 4);
  EXPECT_NEAR(n->value, 0, 1e-12);
  int extrema = 0;
  for (const auto &m : c.tree.nodes)
    extrema += m.type == NodeType::Minimum || m.type == NodeType::Maximum;
  EXPECT_EQ(extrema, 8);
  expect_certified(c, 1);
}

TEST(DegeneratePoints, ACuspSaddleHasItsShapeClassifiedOrNot) {
  // u^4 - w^2: its upper sectors |w| < u^2 are cusps, which a straight ray from the node enters
  // only by dipping below the node's value by up to the leading coefficients' tolerance. Within
  // the reported slack that certifies; where it does not, the cell falls back to its stand-in
  // (counted). Either way the tree has the saddle's shape, its value within the slack of 0.
  for (uint64_t seed : {3, 5, 8}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Computed c{on_grid(4, kCusp, seed), {}, {}};
    c.mesh = build_mesh(c.input);
    c.tree = compute_tree(c.mesh, TreeRequest{}, &c.input).tree;
    ASSERT_TRUE(c.tree.stats.exact);
    const ExactCounts &n = *c.tree.stats.exact;
    EXPECT_EQ(shape(c.tree), "minimum(0,1) minimum(0,1) saddle(2,2) maximum(1,0) maximum(1,0)");
    const double slack = n.fallback_cells > 0 ? 2 * n.fallback_error : n.degenerate_slack;
    EXPECT_EQ(n.fallback_cells > 0, n.degenerate_points == 0);
    EXPECT_LE(std::abs(c.tree.nodes[2].value), slack);
    // The checker sees the cusps exactly (sign arcs on squares around the node; 64 samples per
    // turn miss them).
    const TreeCheckReport report = check_tree(c.tree, c.mesh);
    EXPECT_TRUE(report.ok()) << report.summary();
  }
}

TEST(DegeneratePoints, CriticalVerticesAreClassifiedInTheirCells) {
  // A maximum and a saddle exactly at the vertex (0.5, 0.5) of the unjittered grid (P3), as
  // symmetric data put them: every edge's derivative vanishes there, and along the boundary
  // x = 0.5 and y = 0.5 meet edges whose derivative vanishes at a vertex too. Before, each such
  // cell fell back (19 and 11 cells); now each corner's sectors inside its cell are classified.
  const Field2 peak = [](double x, double y) {
    const double a = x - 0.5, b = y - 0.5;
    return -a * a - b * b + 0.3 * a * a * b;
  };
  const Field2 saddle = [](double x, double y) {
    const double a = x - 0.5, b = y - 0.5;
    return 1.1 * a * a - b * b + 0.3 * a * b * b;
  };
  for (bool is_peak : {true, false}) {
    SCOPED_TRACE(is_peak ? "maximum" : "saddle");
    const Computed c = computed(3, is_peak ? peak : saddle, false);
    const TreeNode *n = node_at_the_point(c.tree, 1e-12, 0.5, 0.5);
    ASSERT_NE(n, nullptr);
    EXPECT_EQ(n->location, NodeLocation::Vertex);
    EXPECT_EQ(n->value, 0);
    if (is_peak) {
      EXPECT_EQ(n->type, NodeType::Maximum);
    } else {
      EXPECT_EQ(n->type, NodeType::Saddle);
      EXPECT_EQ(n->down, 2);
      EXPECT_EQ(n->up, 2);
    }
    EXPECT_GE(c.tree.stats.exact->critical_corners, 6); // the six cells around the vertex
    expect_certified(c, 0);
  }
}

// The classifier alone, on one polynomial of the reference triangle.
BernsteinTriangle on_reference(int d, const Field2 &f) {
  std::vector<double> values(static_cast<std::size_t>(lattice_size(d)));
  for (int b = 0; b <= d; ++b)
    for (int a = 0; a + b <= d; ++a)
      values[static_cast<std::size_t>(lattice_index(d, a, b))] =
          f(static_cast<double>(a) / d, static_cast<double>(b) / d);
  return bernstein_from_lattice_values(values.data(), d);
}

TEST(DegeneratePoints, TheClassifierCountsSectors) {
  // The monkey saddle at (0.47, 0.52) of the reference triangle is outside it: shift it inside.
  const Field2 monkey = [](double x, double y) { return kMonkey(x + 0.2, y + 0.25); };
  const BernsteinTriangle g = on_reference(3, monkey);
  const GradientZeros first = find_gradient_zeros(g);
  ASSERT_GT(first.unresolved + first.budget_exhausted, 0); // Krawczyk cannot certify it
  const DegenerateResolution r = resolve_degenerate_zeros(g, first, {});
  ASSERT_TRUE(r.resolved);
  ASSERT_EQ(r.points.size(), 1u);
  EXPECT_EQ(r.regular, 0);
  const DegenerateCritical &p = r.points[0];
  EXPECT_NEAR(p.uv[0], 0.27, 1e-6);
  EXPECT_NEAR(p.uv[1], 0.27, 1e-6);
  EXPECT_NEAR(p.value, 0, 1e-15);
  EXPECT_EQ(p.rays.lower.size(), 3u);
  EXPECT_EQ(p.rays.upper.size(), 3u);
  // Each sector's point lies in it: below (above) the node's value.
  for (const Vec2 &q : p.rays.lower)
    EXPECT_LT(g(q[0], q[1]), p.value);
  for (const Vec2 &q : p.rays.upper)
    EXPECT_GT(g(q[0], q[1]), p.value);
  for (int s : p.rays.lower_skip)
    EXPECT_EQ(s, 3); // value, gradient and Hessian vanish: the ray starts at third order
  EXPECT_LE(p.slack, 1e-12);
}

TEST(DegeneratePoints, SignArcsOnASquareSeeCuspsExactly) {
  // Around (0.27, 0.27) of the reference triangle: u^4 - w^2 has two lower arcs and two upper
  // arcs |w| < u^2 (at r = 0.01 about 1e-4 wide, between 24 samples per side); the monkey saddle
  // three of each; the inflection one of each; a square off the point one of each.
  auto arcs = [](const Field2 &f, const Vec2 &c, double r) {
    const BernsteinTriangle g =
        on_reference(4, [&](double x, double y) { return f(x + 0.2, y + 0.25); });
    std::vector<SignArc> a;
    const double level = g(c[0], c[1]);
    EXPECT_TRUE(sign_arcs_on_square(g, c, r, level, 1e-15, a));
    int lower = 0, upper = 0;
    for (const SignArc &s : a) {
      ++(s.lower ? lower : upper);
      EXPECT_EQ(g(s.point[0], s.point[1]) < level, s.lower);
    }
    return std::to_string(lower) + " " + std::to_string(upper);
  };
  EXPECT_EQ(arcs(kCusp, {0.27, 0.27}, 0.01), "2 2");
  EXPECT_EQ(arcs(kMonkey, {0.27, 0.27}, 0.01), "3 3");
  EXPECT_EQ(arcs(kInflection, {0.27, 0.27}, 0.01), "1 1");
  EXPECT_EQ(arcs(kFlatMinimum, {0.27, 0.27}, 0.01), "0 1");
  EXPECT_EQ(arcs(kCusp, {0.3, 0.25}, 0.01), "1 1");

  // A monkey saddle one of whose zero lines is the square's diagonal u = -v: a corner lies on
  // the level, the square fails; turned by 0.3 rad it sees the six sectors.
  const Field2 diagonal = [](double x, double y) {
    const double a = (x - 0.3 + y - 0.3) / std::sqrt(2.0), b = (y - x) / std::sqrt(2.0);
    return a * a * a - 3 * a * b * b;
  };
  const BernsteinTriangle g = on_reference(3, diagonal);
  std::vector<SignArc> a;
  EXPECT_FALSE(sign_arcs_on_square(g, {0.3, 0.3}, 0.01, g(0.3, 0.3), 1e-15, a));
  ASSERT_TRUE(sign_arcs_on_square(g, {0.3, 0.3}, 0.01, g(0.3, 0.3), 1e-15, a, 0.3));
  EXPECT_EQ(a.size(), 6u);
}

TEST(DegeneratePoints, UnresolvableZerosAreNotClassified) {
  // A critical curve (the ridge u = 0 of -u^2): not isolated, not classified.
  const Field2 ridge = [](double x, double y) {
    const double u = U(x + 0.2, y + 0.25);
    return -u * u;
  };
  const BernsteinTriangle g = on_reference(2, ridge);
  const GradientZeros first = find_gradient_zeros(g);
  ASSERT_GT(first.unresolved + first.budget_exhausted, 0);
  EXPECT_FALSE(resolve_degenerate_zeros(g, first, {}).resolved);
}

} // namespace
} // namespace hoct
