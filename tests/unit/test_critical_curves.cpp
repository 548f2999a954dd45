// Critical curves (ridges, valleys, curves of saddles) and degenerate critical points: fields
// whose exact trees are known by hand. A curve of critical points is certified as one node per
// cell it crosses (cell/critical_curves.hpp), merged across cells as one flat region; where that
// is not possible (a ridge along mesh edges, the conductor's plateau) the fallback cells' PL
// stand-in breaks a ridge into pieces and a degenerate point into a pair, every such pair within
// twice the stand-in's certified distance from the field, and cancelled.
#include "cell/critical_curves.hpp"
#include "datasets/datasets.hpp"
#include "exact/exact_contour_tree.hpp"
#include "io/tree_json.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"
#include "test_meshes.hpp"
#include "test_refinement_convergence.hpp"
#include "test_tree_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace hoct {
namespace {

using Field2 = std::function<double(double, double)>;

MeshInput on_grid(int n, int degree, const Field2 &f, uint64_t seed = 3) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(n, rng, v, t);
  return testing::lagrange_mesh(
      v, t, [degree](int64_t) { return degree; }, nullptr,
      [&f](const Vec3 &p) { return f(p[0], p[1]); }, rng);
}

MeshInput one_triangle(int degree, const Field2 &f) {
  std::mt19937_64 rng(1);
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<int64_t, 3>> t = {{0, 1, 2}};
  return testing::lagrange_mesh(
      v, t, [degree](int64_t) { return degree; }, nullptr,
      [&f](const Vec3 &p) { return f(p[0], p[1]); }, rng, false);
}

TreeResult tree_of(const MeshInput &in) {
  const Mesh mesh = build_mesh(in);
  return compute_tree(mesh, TreeRequest{}, &in).tree;
}

// Node types ascending by value, as "min", "max", "saddle" words.
std::string types(const TreeResult &t) {
  std::string s;
  for (const auto &n : t.nodes)
    s += std::string(s.empty() ? "" : " ") + to_string(n.type);
  return s;
}

TEST(CriticalCurves, ARidgeFromACornerToAnEdgeMidpointIsOneMaximum) {
  // -(x - y)^2 on one quadratic triangle: the maximum 0 is the segment (0,0)-(0.5,0.5); the two
  // other corners are minima (-1); below 0 the two sides are apart.
  const TreeResult t =
      tree_of(one_triangle(2, [](double x, double y) { return -(x - y) * (x - y); }));
  EXPECT_EQ(types(t), "minimum minimum maximum");
  ASSERT_EQ(t.nodes.size(), 3u);
  EXPECT_NEAR(t.nodes[2].value, 0, 1e-12);
  EXPECT_EQ(t.nodes[2].down, 2);
  EXPECT_NEAR(t.nodes[0].value, -1, 1e-12);
  ASSERT_TRUE(t.stats.exact);
  // Certified as a critical curve, not by the stand-in; the corner (0,0) is on it.
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
  EXPECT_EQ(t.stats.exact->critical_curves, 1);
  EXPECT_GT(t.stats.exact->degenerate_slack, 0);
  EXPECT_LT(t.stats.exact->degenerate_slack, 1e-9);
}

TEST(CriticalCurves, AStraightRidgeAcrossCellsIsOneMaximum) {
  // -(x + y/2 - 0.8)^2 on 32 quadratic cells: the ridge from (0.8, 0) to (0.3, 1) is the
  // maximum; each side is convex, with its minimum at the farthest corner: (0,0) at -0.64 and
  // (1,1) at -0.49.
  const TreeResult t = tree_of(on_grid(4, 2, [](double x, double y) {
    const double s = x + y / 2 - 0.8;
    return -s * s;
  }));
  EXPECT_EQ(types(t), "minimum minimum maximum");
  ASSERT_EQ(t.nodes.size(), 3u);
  EXPECT_NEAR(t.nodes[0].value, -0.64, 1e-12);
  EXPECT_NEAR(t.nodes[1].value, -0.49, 1e-12);
  EXPECT_NEAR(t.nodes[2].value, 0, 1e-12);
  ASSERT_TRUE(t.stats.exact);
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
  EXPECT_GT(t.stats.exact->critical_curves, 4); // one per cell the ridge crosses
  EXPECT_GT(t.nodes[2].merged, 4);
}

TEST(CriticalCurves, ADegenerateCriticalPointIsNoNode) {
  // (x - 0.5)^3 + (y - b)^2: its only critical point (0.5, b) is neither an extremum nor a
  // saddle. The tree: the minimum (0, b) on the left side, the boundary saddle (1, b) on the
  // right side, the maxima at the right corners.
  const double b = 0.3;
  const TreeResult t = tree_of(on_grid(6, 3, [b](double x, double y) {
    return (x - 0.5) * (x - 0.5) * (x - 0.5) + (y - b) * (y - b);
  }));
  EXPECT_EQ(types(t), "minimum saddle maximum maximum");
  ASSERT_EQ(t.nodes.size(), 4u);
  EXPECT_NEAR(t.nodes[0].value, -0.125, 1e-12);
  EXPECT_NEAR(t.nodes[1].value, 0.125, 1e-12);
  EXPECT_NEAR(t.nodes[2].value, 0.125 + b * b, 1e-12);
  EXPECT_NEAR(t.nodes[3].value, 0.125 + (1 - b) * (1 - b), 1e-12);
}

MeshInput on_regular_grid(int n, int degree, const Field2 &f) {
  return testing::lattice_grid(n, degree, f);
}

// "type(down,up)" per node, ascending.
std::string shape(const TreeResult &t) { return testing::tree_shape(t); }

TEST(CriticalCurves, AClosedRidgeIsOneNodeOverTheInsideAndTheOutside) {
  // -(r^2 - 0.09)^2 around (0.5, 0.5), P4 on 128 cells: the circle r = 0.3 is the maximum (0);
  // inside, the centre (-0.0081); outside, the four corners (-0.1681) joined at the four edge
  // midpoints (-0.0256, one flat node).
  const TreeResult t = tree_of(on_grid(8, 4, [](double x, double y) {
    const double s = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) - 0.09;
    return -s * s;
  }));
  EXPECT_EQ(shape(t), "minimum(0,1) minimum(0,1) minimum(0,1) minimum(0,1) saddle(4,1) "
                      "minimum(0,1) maximum(2,0)");
  ASSERT_EQ(t.nodes.size(), 7u);
  EXPECT_NEAR(t.nodes[4].value, -0.0256, 1e-12);
  EXPECT_NEAR(t.nodes[5].value, -0.0081, 1e-12);
  EXPECT_NEAR(t.nodes[6].value, 0, 1e-12);
  ASSERT_TRUE(t.stats.exact);
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
}

TEST(CriticalCurves, ACurvedRidgeIsOneMaximum) {
  // s = y - 0.4 - 0.8 (x - 0.5)^2, f = -s^2 (P4): the parabola s = 0 is the maximum; below it
  // the corners (0,0), (1,0) (-0.36) join at (0.5, 0) (-0.16); above it (0.5, 1) (-0.36).
  const TreeResult t = tree_of(on_grid(8, 4, [](double x, double y) {
    const double s = y - 0.4 - 0.8 * (x - 0.5) * (x - 0.5);
    return -s * s;
  }));
  EXPECT_EQ(shape(t), "minimum(0,1) minimum(0,1) minimum(0,1) saddle(2,1) maximum(2,0)");
  ASSERT_EQ(t.nodes.size(), 5u);
  EXPECT_NEAR(t.nodes[3].value, -0.16, 1e-12);
  EXPECT_NEAR(t.nodes[4].value, 0, 1e-12);
  ASSERT_TRUE(t.stats.exact);
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
}

TEST(CriticalCurves, AValleyAlongMeshEdges) {
  // (x - 0.5)^2 with x = 0.5 a line of mesh edges: the valley is the minimum, the sides x = 0 and
  // x = 1 the maxima. Tilted by 0.1 y: a boundary minimum (0.5, 0), a boundary saddle (0.5, 1),
  // the top corners.
  const TreeResult flat =
      tree_of(on_regular_grid(4, 2, [](double x, double) { return (x - 0.5) * (x - 0.5); }));
  EXPECT_EQ(shape(flat), "minimum(0,2) maximum(1,0) maximum(1,0)");
  ASSERT_TRUE(flat.stats.exact);
  // Certified: the valley's four edges are critical edges for the two cells on each, the other
  // vertical edges level edges; the cells touching the valley at a corner classify it there.
  EXPECT_EQ(flat.stats.exact->fallback_cells, 0);
  EXPECT_EQ(flat.stats.exact->critical_curves, 8);
  EXPECT_EQ(flat.stats.exact->level_edges, 24);
  const TreeResult tilted = tree_of(
      on_regular_grid(4, 2, [](double x, double y) { return (x - 0.5) * (x - 0.5) + 0.1 * y; }));
  EXPECT_EQ(shape(tilted), "minimum(0,1) saddle(1,2) maximum(1,0) maximum(1,0)");
  ASSERT_EQ(tilted.nodes.size(), 4u);
  EXPECT_NEAR(tilted.nodes[1].value, 0.1, 1e-12);
}

TEST(CriticalCurves, RidgesAndValleysAlongMeshEdgesAreCertified) {
  struct Case {
    const char *what;
    int degree;
    Field2 f;
    const char *shape;
    double curve_value;
    int64_t fallback = 0; // expected fallback cells
  };
  const std::vector<Case> cases = {
      // The diagonal y = x is a line of mesh edges: the ridge is the maximum, the corners
      // (1, 0) and (0, 1) the minima.
      {"ridge on the diagonal", 2, [](double x, double y) { return -(x - y) * (x - y); },
       "minimum(0,1) minimum(0,1) maximum(2,0)", 0},
      // A valley whose depth varies along it (P3: q = 1 + y / 2 in the cells' frames).
      {"valley of varying depth", 3,
       [](double x, double y) { return 1 + (x - 0.5) * (x - 0.5) * (1 + 0.5 * y); },
       "minimum(0,2) maximum(1,0) maximum(1,0)", 1},
      // A ridge on a line of edges between two valleys inside cells (P4): s = x - 0.5,
      // -s^2 (1 - 6 s^2); the valleys at |s| = 12^-1/2 (-1/24), the sides x = 0, 1 at 0.125.
      // The ridge's cells are certified; the valleys' 16 cells lie beside level edges, where
      // the curve cover's budget (256 boxes, against plateaus' borders) is short of what a
      // quartic valley takes: they fall back, the tree still right.
      {"ridge between valleys", 4,
       [](double x, double) {
         const double s = x - 0.5;
         return -s * s * (1 - 6 * s * s);
       },
       "minimum(0,2) minimum(0,2) maximum(2,0) maximum(1,0) maximum(1,0)", 0, 16},
      // The valley at 1e5 (pascal): certified the same, within the data's precision.
      {"valley at 1e5", 2, [](double x, double) { return 1e5 + (x - 0.5) * (x - 0.5); },
       "minimum(0,2) maximum(1,0) maximum(1,0)", 1e5},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.what);
    const MeshInput in = on_regular_grid(4, c.degree, c.f);
    const Mesh mesh = build_mesh(in);
    const TreeResult t = compute_tree(mesh, TreeRequest{}, &in).tree;
    EXPECT_EQ(shape(t), c.shape);
    ASSERT_TRUE(t.stats.exact);
    EXPECT_EQ(t.stats.exact->fallback_cells, c.fallback);
    EXPECT_GT(t.stats.exact->critical_curves, 0);
    bool found = false;
    for (const auto &n : t.nodes)
      found = found || std::abs(n.value - c.curve_value) < 1e-12 * (1 + std::abs(c.curve_value));
    EXPECT_TRUE(found) << "no node at the curve's value " << c.curve_value;
    if (c.fallback == 0) // (with fallback cells the stand-in's values are within its slack)
      testing::expect_refinements_converge(mesh, in, t);
  }
}

TEST(CriticalCurves, ACurveOfSaddlesIsOneSaddle) {
  // (x - 0.5)^2 (y - 0.45), P3: the line x = 0.5 is critical at 0, a valley above y = 0.45 and a
  // ridge below: one node with the two negative sides below it and the two positive sides above.
  const TreeResult t =
      tree_of(on_grid(6, 3, [](double x, double y) { return (x - 0.5) * (x - 0.5) * (y - 0.45); }));
  EXPECT_EQ(shape(t), "minimum(0,1) minimum(0,1) saddle(2,2) maximum(1,0) maximum(1,0)");
  ASSERT_EQ(t.nodes.size(), 5u);
  ASSERT_TRUE(t.stats.exact);
  // Certified, the degenerate point where ridge turns valley (0.5, 0.45) included.
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
  EXPECT_GT(t.stats.exact->critical_curves, 0);
  EXPECT_NEAR(t.nodes[2].value, 0, 1e-12);
  EXPECT_NEAR(t.nodes[0].value, -0.1125, 1e-12);
  EXPECT_NEAR(t.nodes[4].value, 0.1375, 1e-12);
}

TEST(CriticalCurves, ASaddleOnAMeshEdgeIsCertified) {
  // (x - 0.5)^2 - 2 (y - 0.375)^2, P2 on the lattice grid (x = 0.5 is a line of mesh edges): the
  // saddle lies on a mesh edge, where its normal derivative vanishes; both cells classify the
  // small region holding it (four sectors), and the vertices on x = 0.5, where the gradient is
  // orthogonal to the horizontal edges, by their corner triangles.
  const auto f = [](double x, double y) {
    return (x - 0.5) * (x - 0.5) - 2 * (y - 0.375) * (y - 0.375);
  };
  const TreeResult t = tree_of(on_regular_grid(4, 2, f));
  ASSERT_TRUE(t.stats.exact);
  EXPECT_EQ(t.stats.exact->fallback_cells, 0);
  EXPECT_GT(t.stats.exact->critical_curves, 0);
  EXPECT_EQ(shape(t), "minimum(0,1) minimum(0,1) saddle(2,2) maximum(1,0) maximum(1,0)");
  ASSERT_EQ(t.nodes.size(), 5u);
  EXPECT_NEAR(t.nodes[2].value, 0, 1e-12);
  EXPECT_NEAR(t.nodes[2].position[0], 0.5, 1e-3);
  EXPECT_NEAR(t.nodes[2].position[1], 0.375, 1e-3);
}

// Pairs the stand-in does not resolve are named: a fallback node and a persistence within twice
// the slack, counted in the statistics and flagged "uncertain" in the JSON. (Random data clamped
// to a plateau: its border cells, kinked inside, fall back.)
TEST(CriticalCurves, PairsWithinTheSlackAreFlagged) {
  DatasetOptions o;
  o.cells = 2000;
  o.degree = 2;
  o.plateau = 10;
  const MeshInput in = generate_dataset("random", o);
  const TreeResult t = tree_of(in);
  ASSERT_TRUE(t.stats.exact && t.stats.pairs_within_fallback_slack);
  const double slack = t.stats.exact->fallback_error;
  ASSERT_GT(slack, 0);
  int64_t expected = 0, flagged = 0;
  for (const auto &p : t.pairs) {
    const bool near =
        (t.nodes[p.birth].fallback || t.nodes[p.death].fallback) && p.persistence() <= 2 * slack;
    expected += near;
    flagged += t.uncertain(p);
    if (near) {
      EXPECT_TRUE(t.uncertain(p));
    }
  }
  EXPECT_GT(expected, 0);
  EXPECT_EQ(*t.stats.pairs_within_fallback_slack, expected);
  const std::string json = tree_to_json(t, false);
  int64_t in_json = 0;
  for (std::size_t at = json.find("\"uncertain\""); at != std::string::npos;
       at = json.find("\"uncertain\"", at + 1))
    ++in_json;
  EXPECT_EQ(in_json, flagged);
}

// Independent truth: the PL trees of ever finer refinements of the same field converge to the
// exact tree (bottleneck distance of the diagrams shrinking towards 0).
TEST(CriticalCurves, RefinementsConvergeToTheExactTree) {
  const std::vector<MeshInput> fields = {
      one_triangle(2, [](double x, double y) { return -(x - y) * (x - y); }),
      on_grid(4, 2,
              [](double x, double y) {
                const double s = x + y / 2 - 0.8;
                return -s * s;
              }),
      on_grid(6, 3, [](double x, double y) {
        return (x - 0.5) * (x - 0.5) * (x - 0.5) + (y - 0.3) * (y - 0.3);
      })};
  for (std::size_t f = 0; f < fields.size(); ++f) {
    SCOPED_TRACE("field " + std::to_string(f));
    const Mesh mesh = build_mesh(fields[f]);
    const TreeResult exact = compute_tree(mesh, TreeRequest{}, &fields[f]).tree;
    testing::expect_refinements_converge(mesh, fields[f], exact);
  }
}

// The classifier itself, on one reference triangle (Bernstein coefficients from values at the
// lattice points).
BernsteinTriangle from_values(int degree, const Field2 &f) {
  std::vector<double> values(static_cast<std::size_t>(lattice_size(degree))), coef(values.size());
  for (int b = 0; b <= degree; ++b)
    for (int a = 0; a + b <= degree; ++a)
      values[static_cast<std::size_t>(lattice_index(degree, a, b))] =
          f(static_cast<double>(a) / degree, static_cast<double>(b) / degree);
  bernstein_from_lattice_values(values.data(), degree, coef.data());
  return BernsteinTriangle(degree, coef);
}

TEST(CriticalCurveClassifier, ARidgeHasItsTwoSidesAndItsBoundaryPoints) {
  // -(u - v)^2: the segment from corner 0 to the hypotenuse's midpoint.
  const BernsteinTriangle g = from_values(2, [](double u, double v) { return -(u - v) * (u - v); });
  const std::vector<Vec2> boundary = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}};
  const CurveResolution r = resolve_critical_curves(g, boundary);
  ASSERT_TRUE(r.resolved);
  ASSERT_EQ(r.curves.size(), 1u);
  const CriticalCurve &c = r.curves[0];
  EXPECT_NEAR(c.value, 0, 1e-15);
  EXPECT_EQ(c.rays.lower.size(), 2u); // one per side
  EXPECT_EQ(c.rays.upper.size(), 0u);
  EXPECT_EQ(c.boundary_nodes, (std::vector<int>{0, 3}));
  EXPECT_LT(c.slack, 1e-12);
  for (const Vec2 &a : c.anchors)
    EXPECT_NEAR(a[0], a[1], 1e-12); // on the ridge
  // Each ray starts on the ridge and ends on its side.
  for (std::size_t i = 0; i < c.rays.lower.size(); ++i)
    EXPECT_LT(g(c.rays.lower[i][0], c.rays.lower[i][1]), -1e-6);
}

TEST(CriticalCurveClassifier, AValleyHasItsTwoSidesAbove) {
  // (u - 0.3)^2 (v + 0.5), cubic: the line u = 0.3 is a valley of value 0, from the bottom edge
  // to the hypotenuse.
  const BernsteinTriangle g =
      from_values(3, [](double u, double v) { return (u - 0.3) * (u - 0.3) * (v + 0.5); });
  const std::vector<Vec2> boundary = {{0, 0}, {1, 0}, {0, 1}, {0.3, 0}, {0.3, 0.7}};
  const CurveResolution r = resolve_critical_curves(g, boundary);
  ASSERT_TRUE(r.resolved);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_NEAR(r.curves[0].value, 0, 1e-14);
  EXPECT_EQ(r.curves[0].rays.lower.size(), 0u);
  EXPECT_EQ(r.curves[0].rays.upper.size(), 2u);
  EXPECT_EQ(r.curves[0].boundary_nodes, (std::vector<int>{3, 4}));
}

TEST(CriticalCurveClassifier, AMonkeySaddleIsOneNodeWithSixSectors) {
  // x^3 - 3 x y^2 around (0.3, 0.3): the Hessian vanishes there; the box around it where g
  // varies within the target is the node's region.
  const BernsteinTriangle g = from_values(3, [](double u, double v) {
    const double x = u - 0.3, y = v - 0.3;
    return x * x * x - 3 * x * y * y;
  });
  const CurveResolution r = resolve_critical_curves(g, std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}});
  ASSERT_TRUE(r.resolved);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(r.curves[0].rays.lower.size(), 3u);
  EXPECT_EQ(r.curves[0].rays.upper.size(), 3u);
  EXPECT_NEAR(r.curves[0].uv[0], 0.3, 1e-3);
  EXPECT_NEAR(r.curves[0].uv[1], 0.3, 1e-3);
}

TEST(CriticalCurveClassifier, RefusesWhatItCannotCertify) {
  // A sloping valley: no zero at all.
  EXPECT_FALSE(resolve_critical_curves(
                   from_values(2, [](double u, double v) { return (u - v) * (u - v) + 1e-3 * u; }),
                   std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}})
                   .resolved);
  // An edge node near the ridge that is not on it, and not reachable by a certified ray (a
  // point of the ridge's own level off the curve).
  EXPECT_FALSE(
      resolve_critical_curves(from_values(2, [](double u, double v) { return -(u - v) * (u - v); }),
                              std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}, {0.5 + 1e-7, 0.5 - 1e-7}})
          .resolved);
}

} // namespace
} // namespace hoct
