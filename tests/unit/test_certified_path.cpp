// Certified monotone paths inside one cell (certify_below, connect_lower) against analytic fields:
// sign certificates of segment restrictions checked by dense sampling of the closed-form field
// and its derivative, and traced paths checked point by point against the closed-form field and
// gradient (strict descent, steps along the negative gradient, exits on the expected edge).
#include "cell/cell_nodes.hpp"
#include "cell/certified_path.hpp"
#include "poly/bernstein_triangle.hpp"
#include "poly/lattice.hpp"
#include "test_bernstein_forms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace hoct {
namespace {

using Fn = std::function<double(double, double)>;
using Grad = std::function<Vec2(double, double)>;

using testing::interpolate;
using testing::separable;

// The directional derivative w . grad g as a polynomial of degree d - 1.
BernsteinTriangle directional(const BernsteinTriangle &g, const Vec2 &w) {
  const BernsteinTriangle gu = g.du(), gv = g.dv();
  std::vector<double> c(gu.coefficients().size());
  for (std::size_t i = 0; i < c.size(); ++i)
    c[i] = w[0] * gu.coefficients()[i] + w[1] * gv.coefficients()[i];
  return BernsteinTriangle(gu.degree(), c);
}

BernsteinTriangle negated(BernsteinTriangle g) {
  for (double &c : g.coefficients())
    c = -c;
  return g;
}

Vec2 lerp(const Vec2 &p, const Vec2 &q, double t) {
  return {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
}

// Min and max of f on the closed segment p -> q at n + 1 equally spaced points.
std::pair<double, double> sampled_range(const Fn &f, const Vec2 &p, const Vec2 &q, int n = 2000) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k <= n; ++k) {
    const Vec2 x = lerp(p, q, static_cast<double>(k) / n);
    const double y = f(x[0], x[1]);
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  return {lo, hi};
}

double dist(const Vec2 &a, const Vec2 &b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

// A cell's nodes: the three corners (refs 0..2) and any further points, values from f; chains
// with the given interior nodes per edge (indices, ascending along the edge).
struct TestCell {
  CellNodes cn;
  std::vector<double> values;
  explicit TestCell(const Fn &f) {
    static constexpr double kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    for (int k = 0; k < 3; ++k)
      add({kCorner[k][0], kCorner[k][1]}, f(kCorner[k][0], kCorner[k][1]));
    for (int k = 0; k < 3; ++k) {
      cn.chain[k] = {k, (k + 1) % 3};
      cn.chain_s[k] = {0.0, 1.0};
    }
  }
  int add(const Vec2 &uv, double value) {
    const int idx = static_cast<int>(cn.nodes.size());
    cn.nodes.push_back({uv, value, idx});
    values.push_back(value);
    return idx;
  }
  // An edge node of local edge k at parameter s (inserted into the chain).
  int add_edge_node(int k, double s, const Fn &f) {
    const Vec2 p = point_on_edge(k, s);
    const int idx = add(p, f(p[0], p[1]));
    cn.chain[k].insert(cn.chain[k].end() - 1, idx);
    cn.chain_s[k].insert(cn.chain_s[k].end() - 1, s);
    return idx;
  }
  std::vector<double> negated_values() const {
    std::vector<double> v(values);
    for (double &x : v)
      x = -x;
    return v;
  }
};

// Every segment of a path sampled strictly below `level`, values strictly decreasing from
// point to point, the path starting at `start`.
void expect_strict_descent(const Fn &f, const std::vector<Vec2> &path, const Vec2 &start,
                           double level) {
  ASSERT_GE(path.size(), 2u);
  EXPECT_EQ(path.front(), start);
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_LT(f(path[i][0], path[i][1]), f(path[i - 1][0], path[i - 1][1]))
        << "path point " << i << " at (" << path[i][0] << ", " << path[i][1] << ")";
    // The first segment starts at the level itself; its interior must be strictly below.
    const Vec2 from = i == 1 ? lerp(path[0], path[1], 1e-3) : path[i - 1];
    EXPECT_LT(sampled_range(f, from, path[i], 400).second, level) << "path segment " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Sign certificates of segment restrictions.

// (u - 1/2)^3 + (3/4) v, exactly: the Bernstein coefficients of (u - 1/2)^3 in degree 3 are
// (-1/8, 1/8, -1/8, 1/8), those of (3/4) v are (0, 1/4, 1/2, 3/4). Its u-derivative
// 3 (u - 1/2)^2 vanishes (without changing sign) on u = 1/2.
const Fn kCubic = [](double u, double v) { return std::pow(u - 0.5, 3) + 0.75 * v; };
const Grad kCubicGrad = [](double u, double) -> Vec2 { return {3 * (u - 0.5) * (u - 0.5), 0.75}; };
BernsteinTriangle cubic() {
  return separable({-0.125, 0.125, -0.125, 0.125}, {0, 0.25, 0.5, 0.75});
}

double directional_value(const Grad &grad, const Vec2 &x, const Vec2 &w) {
  const Vec2 gr = grad(x[0], x[1]);
  return gr[0] * w[0] + gr[1] * w[1];
}

TEST(CertifiedPath, ExactBernsteinFormsMatchTheFields) {
  const BernsteinTriangle g = cubic();
  for (double u = 0; u <= 1; u += 0.125)
    for (double v = 0; u + v <= 1; v += 0.125)
      ASSERT_NEAR(g(u, v), kCubic(u, v), 1e-15) << u << " " << v;
}

TEST(CertifiedPath, MonotoneSegmentCertifies) {
  const BernsteinTriangle g = cubic();
  // Two segments on which the derivative along the segment has a strict sign: along u over
  // [1/8, 3/8] (g decreasing from p to q), and a slanted one on which the v-slope dominates.
  const struct {
    Vec2 p, q;
  } cases[] = {{{0.375, 0.25}, {0.125, 0.25}}, {{0.25, 0.0625}, {0.5, 0.5}}};
  for (const auto &c : cases) {
    const Vec2 w = {c.q[0] - c.p[0], c.q[1] - c.p[1]};
    const BernsteinTriangle dw = directional(g, w);
    const Fn analytic = [&](double u, double v) {
      return directional_value(kCubicGrad, {u, v}, w);
    };
    const auto [lo, hi] = sampled_range(analytic, c.p, c.q);
    const bool decreasing = hi < 0;
    ASSERT_TRUE(decreasing || lo > 0) << "test setup: the derivative must have a strict sign";
    // The certificate of the sign that holds, never of the other.
    EXPECT_TRUE(certify_below(decreasing ? dw : negated(dw), c.p, c.q, 0, 0));
    EXPECT_FALSE(certify_below(decreasing ? negated(dw) : dw, c.p, c.q, 0, 0));
    // And g itself, decreasing along the segment, stays below its start value after it.
    if (decreasing) {
      const Vec2 a = lerp(c.p, c.q, 1e-3);
      EXPECT_TRUE(certify_below(g, a, c.q, kCubic(c.p[0], c.p[1]), 0));
      EXPECT_LT(sampled_range(kCubic, a, c.q).second, kCubic(c.p[0], c.p[1]));
    }
  }
}

TEST(CertifiedPath, SignChangingDerivativeDoesNotCertify) {
  // g = (u - 1/2)^2 - v/4 along w = (3/4, -3/8): w . grad g = (3/2)(u - 1/2) + 3/32 changes sign
  // at u = 7/16 inside the segment.
  const Fn f = [](double u, double v) { return (u - 0.5) * (u - 0.5) - 0.25 * v; };
  const BernsteinTriangle g = separable({0.25, -0.25, 0.25}, {0, -0.125, -0.25});
  ASSERT_NEAR(g(0.3, 0.2), f(0.3, 0.2), 1e-15);
  const Vec2 p = {0.125, 0.5}, q = {0.875, 0.125}, w = {0.75, -0.375};
  const Fn analytic = [&](double u, double) { return 2 * (u - 0.5) * w[0] - 0.25 * w[1]; };
  const auto [lo, hi] = sampled_range(analytic, p, q);
  ASSERT_LT(lo, 0);
  ASSERT_GT(hi, 0);
  const BernsteinTriangle dw = directional(g, w);
  for (int depth : {0, 6, 20}) {
    EXPECT_FALSE(certify_below(dw, p, q, 0, 0, depth)) << depth;
    EXPECT_FALSE(certify_below(negated(dw), p, q, 0, 0, depth)) << depth;
  }
  // Either half alone, away from the sign change, certifies its sign.
  const Vec2 m1 = lerp(p, q, 0.3), m2 = lerp(p, q, 0.6);
  ASSERT_LT(sampled_range(analytic, p, m1).second, 0);
  ASSERT_GT(sampled_range(analytic, m2, q).first, 0);
  EXPECT_TRUE(certify_below(dw, p, m1, 0, 0));
  EXPECT_TRUE(certify_below(negated(dw), m2, q, 0, 0));
}

TEST(CertifiedPath, DerivativeTouchingZeroDoesNotCertify) {
  // Along u through u = 1/2 the derivative 3 (u - 1/2)^2 is >= 0 with a double zero: g increases
  // (strictly, through an inflection) but the derivative has no strict sign, and no subdivision
  // depth may certify it. Dyadic points: the restriction is computed exactly.
  const BernsteinTriangle g = cubic();
  const Vec2 p = {0.25, 0.25}, q = {0.75, 0.25}, w = {0.5, 0};
  const BernsteinTriangle dw = directional(g, w);
  const Fn analytic = [&](double u, double v) { return directional_value(kCubicGrad, {u, v}, w); };
  const auto [lo, hi] = sampled_range(analytic, p, q);
  EXPECT_EQ(lo, 0.0); // attained at the midpoint, which the sampling hits
  EXPECT_GT(hi, 0.0);
  for (int depth : {0, 1, 6, 30})
    EXPECT_FALSE(certify_below(negated(dw), p, q, 0, 0, depth)) << depth;
  // A touching zero at an end of the segment is no strict sign either.
  EXPECT_FALSE(certify_below(negated(dw), p, {0.5, 0.25}, 0, 0));
  // Stopping short of it, the sign is strict and certified.
  EXPECT_TRUE(certify_below(negated(dw), p, {0.4375, 0.25}, 0, 0));
}

TEST(CertifiedPath, SubdivisionTightensTheHull) {
  // Edge 0 carries the Bernstein coefficients (-1, 1, -1), -(1 - 2t)^2: max 0 at t = 1/2, below
  // 1/10, while the middle coefficient is not. One halving certifies it; without subdivision (or
  // with a skip, which disables it) it is not.
  const BernsteinTriangle g = separable({-1, 1, -1}, {0, 0, 0});
  const Vec2 p = {0, 0}, q = {1, 0};
  const Fn f = [](double u, double) { return -(1 - 2 * u) * (1 - 2 * u); };
  ASSERT_NEAR(g(0.3, 0.4), f(0.3, 0.4), 1e-15);
  ASSERT_EQ(sampled_range(f, p, q).second, 0.0);
  EXPECT_FALSE(certify_below(g, p, q, 0.1, 0, 0));
  EXPECT_TRUE(certify_below(g, p, q, 0.1, 0, 1));
  EXPECT_TRUE(certify_below(g, p, q, 0.1, 0));
  EXPECT_FALSE(certify_below(g, p, q, 0.1, 1));
  // Below the maximum itself no depth certifies.
  EXPECT_FALSE(certify_below(g, p, q, -1e-3, 0, 40));
}

TEST(CertifiedPath, RandomSegmentsAreSoundAgainstSampling) {
  // Random cubics and quartics (monomial form, evaluated directly), random segments, thresholds
  // around the sampled maximum: a certificate implies the sampled maximum is below the
  // threshold, and clear cases (well below, well above) are decided as expected.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1, 1), P(0, 1);
  int certified = 0, refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int d = 3 + trial % 2;
    std::vector<double> a(static_cast<std::size_t>((d + 1) * (d + 1)), 0.0);
    for (int i = 0; i <= d; ++i)
      for (int j = 0; i + j <= d; ++j)
        a[static_cast<std::size_t>(i * (d + 1) + j)] = U(rng);
    const Fn f = [&](double u, double v) {
      double s = 0;
      for (int i = 0; i <= d; ++i)
        for (int j = 0; i + j <= d; ++j)
          s += a[static_cast<std::size_t>(i * (d + 1) + j)] * std::pow(u, i) * std::pow(v, j);
      return s;
    };
    const BernsteinTriangle g = interpolate(d, f);
    auto point = [&]() -> Vec2 {
      const double x = P(rng), y = P(rng);
      return x + y <= 1 ? Vec2{x, y} : Vec2{1 - x, 1 - y};
    };
    const Vec2 p = point(), q = point();
    const double hi = sampled_range(f, p, q).second;
    const double thr = hi + 0.2 * U(rng);
    const bool ok = certify_below(g, p, q, thr, 0);
    if (std::abs(thr - hi) < 1e-9)
      continue;
    if (ok) {
      EXPECT_LT(hi, thr) << "trial " << trial;
      ++certified;
    } else {
      ++refused;
    }
    if (hi >= thr) {
      EXPECT_FALSE(ok) << "trial " << trial;
    }
    // Far below the threshold (a generous gap for the depth-6 hull): certified.
    if (thr - hi > 0.1) {
      EXPECT_TRUE(ok) << "trial " << trial;
    }
  }
  EXPECT_GT(certified, 50);
  EXPECT_GT(refused, 50);
}

// ---------------------------------------------------------------------------------------------
// connect_lower at and near critical points.

// A maximum at (0.3, 0.25) with value 0.
const Fn kPeak = [](double u, double v) {
  return -(u - 0.3) * (u - 0.3) - (v - 0.25) * (v - 0.25);
};

TEST(CertifiedPath, SkipIgnoresOnlyTheCoefficientsAtTheLevel) {
  // At a critical point the first two coefficients of the restriction are the level up to
  // rounding: certified below level - margin only when both are skipped.
  const BernsteinTriangle g = interpolate(2, kPeak);
  PathField pf;
  pf.assign(g, false);
  ASSERT_GT(pf.margin, 0);
  const Vec2 c = {0.3, 0.25};
  const double level = kPeak(c[0], c[1]), thr = level - pf.margin;
  for (const Vec2 &s : {Vec2{0.4, 0.25}, Vec2{0.3, 0.1}, Vec2{0.1, 0.5}}) {
    EXPECT_TRUE(certify_below(g, c, s, thr, 2));
    EXPECT_FALSE(certify_below(g, c, s, thr, 1));
    EXPECT_FALSE(certify_below(g, c, s, thr, 0));
  }
  // connect_lower likewise: with skip 2 the maximum reaches a lower node (any corner: the whole
  // cell but the peak lies below it), with skip 1 its first step never certifies.
  TestCell cell(kPeak);
  for (const Vec2 &dir : {Vec2{1, 0}, Vec2{0, -1}, Vec2{-1, 1}}) {
    PathCounters counters;
    std::vector<Vec2> path;
    const int m = connect_lower(pf, cell.cn, cell.values, c, level, dir, 2, counters, &path);
    ASSERT_GE(m, 0);
    EXPECT_LT(cell.values[m], thr);
    EXPECT_EQ(path.back(), cell.cn.nodes[m].uv);
    expect_strict_descent(kPeak, path, c, level);
    // The first step leaves along dir.
    const Vec2 s = path[1];
    EXPECT_NEAR((s[0] - c[0]) * dir[1] - (s[1] - c[1]) * dir[0], 0, 1e-12);
    EXPECT_GT((s[0] - c[0]) * dir[0] + (s[1] - c[1]) * dir[1], 0);
    EXPECT_EQ(connect_lower(pf, cell.cn, cell.values, c, level, dir, 1, counters), -1);
  }
}

// The quadratic saddle (u - 1/3)^2 - (v - 1/3)^2 at (1/3, 1/3), value 0: lower sectors along
// +-v, upper along +-u. Edge nodes: the minimum (1/3, 0) of edge 0 (value -1/9) and the maximum
// (0, 1/3) of edge 2 (value 1/9); edge 1 is linear.
const Fn kSaddle = [](double u, double v) {
  return (u - 1.0 / 3) * (u - 1.0 / 3) - (v - 1.0 / 3) * (v - 1.0 / 3);
};

struct SaddleCell {
  BernsteinTriangle g = interpolate(2, kSaddle);
  TestCell cell{kSaddle};
  int e0, e2;
  Vec2 c = {1.0 / 3, 1.0 / 3};
  SaddleCell() {
    e0 = cell.add_edge_node(0, 1.0 / 3, kSaddle);
    e2 = cell.add_edge_node(2, 2.0 / 3, kSaddle);
    cell.add(c, 0.0);
  }
};

TEST(CertifiedPath, SaddleSectorsReachTheirNodes) {
  SaddleCell s;
  PathField down, up;
  down.assign(s.g, false);
  up.assign(s.g, true);
  EXPECT_EQ(up.margin, down.margin);
  EXPECT_NEAR(up.g(0.2, 0.7), -kSaddle(0.2, 0.7), 1e-15);
  const std::vector<double> neg = s.cell.negated_values();
  const Fn neg_saddle = [](double u, double v) { return -kSaddle(u, v); };
  const struct {
    Vec2 dir;
    bool ascending;
    int expected;
  } cases[] = {
      {{0, -1}, false, s.e0}, {{0, 1}, false, 2}, {{1, 0}, true, 1}, {{-1, 0}, true, s.e2}};
  for (const auto &k : cases) {
    PathCounters counters;
    std::vector<Vec2> path;
    const int m =
        connect_lower(k.ascending ? up : down, s.cell.cn, k.ascending ? neg : s.cell.values, s.c,
                      0.0, k.dir, 2, counters, &path);
    EXPECT_EQ(m, k.expected) << k.dir[0] << " " << k.dir[1];
    if (m < 0)
      continue;
    EXPECT_EQ(counters.direct, 1);
    EXPECT_EQ(counters.traced, 0);
    EXPECT_EQ(path.back(), s.cell.cn.nodes[m].uv);
    expect_strict_descent(k.ascending ? neg_saddle : kSaddle, path, s.c, 0.0);
  }
}

TEST(CertifiedPath, WrongDirectionFromSaddleIsNotCertified) {
  SaddleCell s;
  PathField down;
  down.assign(s.g, false);
  // From the saddle, descending paths cannot leave along an ascending direction (+-u), nor along
  // the zero-level lines between the sectors, on which g is 0: inside the margin.
  for (const Vec2 &dir : {Vec2{1, 0}, Vec2{-1, 0}, Vec2{1, 1}, Vec2{-1, -1}, Vec2{1, -1}}) {
    PathCounters counters;
    EXPECT_EQ(connect_lower(down, s.cell.cn, s.cell.values, s.c, 0.0, dir, 2, counters), -1)
        << dir[0] << " " << dir[1];
  }
  // From a start 1e-7 off the saddle along u (a computed critical point's error), its level
  // 1e-14 inside the margin: still not descending along +-u (g >= level - margin on those
  // rays), while the lower sector along -v still reaches its node.
  const Vec2 c = {1.0 / 3 + 1e-7, 1.0 / 3};
  const double level = kSaddle(c[0], c[1]);
  ASSERT_GT(level, 0);
  ASSERT_LT(level, down.margin);
  for (const Vec2 &dir : {Vec2{1, 0}, Vec2{-1, 0}}) {
    PathCounters counters;
    EXPECT_EQ(connect_lower(down, s.cell.cn, s.cell.values, c, level, dir, 2, counters), -1)
        << dir[0];
    EXPECT_GT(sampled_range(kSaddle, c, {c[0] + 0.25 * dir[0], c[1]}).first, level - down.margin);
  }
  PathCounters counters;
  EXPECT_EQ(connect_lower(down, s.cell.cn, s.cell.values, c, level, {0, -1}, 2, counters), s.e0);
}

TEST(CertifiedPath, MarginExcludesShallowTargets) {
  // A node on the lower sector's rim, nearer to the first step's end than the edge node, whose
  // value is below the level by half the margin: not a target (its certificate would be within
  // rounding of the level). Ten times the margin below, the same place is the target.
  for (const double depth : {0.5, 5.0}) {
    SaddleCell s;
    PathField down;
    down.assign(s.g, false);
    // On (5/12, 1/4 - e): g = 1/144 - (1/12 + e)^2 = -e/6 - e^2.
    const double e = 6 * depth * down.margin;
    const Vec2 rim = {5.0 / 12, 0.25 - e};
    const double value = kSaddle(rim[0], rim[1]);
    ASSERT_NEAR(value, -depth * down.margin, 1e-3 * down.margin);
    const int shallow = s.cell.add(rim, value);
    PathCounters counters;
    std::vector<Vec2> path;
    const int m =
        connect_lower(down, s.cell.cn, s.cell.values, s.c, 0.0, {0, -1}, 2, counters, &path);
    ASSERT_GE(path.size(), 2u);
    // The setup: the rim node is the nearest candidate from the first step's end.
    ASSERT_LT(dist(path[1], rim), dist(path[1], s.cell.cn.nodes[s.e0].uv));
    EXPECT_EQ(m, depth < 1 ? s.e0 : shallow) << depth;
  }
}

// ---------------------------------------------------------------------------------------------
// Descent steps.

TEST(CertifiedPath, DescentStepsGoStrictlyDown) {
  // A narrow curved valley K (v - p(u))^2 + u, p(u) = 0.15 + 0.6 u^2, falling towards its end
  // (0, 0.15) on edge 2, the only node below the start's level 1/2: no straight segment from the
  // start reaches it (the valley bends away), descent steps along the negative gradient do.
  const double K = 300;
  const Fn f = [K](double u, double v) {
    const double r = v - 0.15 - 0.6 * u * u;
    return K * r * r + u;
  };
  const Grad grad = [K](double u, double v) -> Vec2 {
    const double r = v - 0.15 - 0.6 * u * u;
    return {1 - 2.4 * K * r * u, 2 * K * r};
  };
  const BernsteinTriangle g = interpolate(4, f);
  TestCell cell(f);
  const int end = cell.add_edge_node(2, 0.85, f);
  for (int k = 0; k < 3; ++k)
    ASSERT_GT(cell.values[k], 1.0);
  PathField pf;
  pf.assign(g, false);
  const Vec2 c = {0.5, 0.3};
  const double level = f(c[0], c[1]);
  PathCounters counters;
  std::vector<Vec2> path;
  const int m = connect_lower(pf, cell.cn, cell.values, c, level, {-1, 0}, 1, counters, &path);
  ASSERT_EQ(m, end);
  EXPECT_EQ(counters.direct, 0);
  EXPECT_EQ(counters.traced, 1);
  EXPECT_GE(counters.steps, 2);
  ASSERT_GE(path.size(), 4u);
  EXPECT_EQ(path.back(), cell.cn.nodes[end].uv);
  expect_strict_descent(f, path, c, level);
  // Straight from the first step's end the valley's end is out of reach (above the level).
  EXPECT_GT(sampled_range(f, path[1], cell.cn.nodes[end].uv).second, level);
  // Each descent step follows the negative gradient at its start.
  for (std::size_t i = 2; i + 1 < path.size(); ++i) {
    const Vec2 d = {path[i][0] - path[i - 1][0], path[i][1] - path[i - 1][1]};
    const Vec2 gr = grad(path[i - 1][0], path[i - 1][1]);
    const double n = std::hypot(d[0], d[1]) * std::hypot(gr[0], gr[1]);
    ASSERT_GT(n, 0);
    EXPECT_NEAR((d[0] * gr[1] - d[1] * gr[0]) / n, 0, 1e-9) << "step " << i;
    EXPECT_LT((d[0] * gr[0] + d[1] * gr[1]) / n, -0.999) << "step " << i;
    // Not past the first minimum along the ray: still descending at the step's end, or there.
    const Vec2 ge = grad(path[i][0], path[i][1]);
    EXPECT_LT((d[0] * ge[0] + d[1] * ge[1]) / n, 1e-6) << "step " << i;
  }
  // Ascending paths: the upper connection of -f (the field negated by PathField, the values by
  // the caller, the start's level -(-f(c)) = f(c)) climbs the same way, strictly up in -f.
  const BernsteinTriangle neg_g = interpolate(4, [&](double u, double v) { return -f(u, v); });
  PathField up;
  up.assign(neg_g, true);
  TestCell neg_cell([&](double u, double v) { return -f(u, v); });
  neg_cell.add_edge_node(2, 0.85, [&](double u, double v) { return -f(u, v); });
  PathCounters up_counters;
  std::vector<Vec2> up_path;
  EXPECT_EQ(connect_lower(up, neg_cell.cn, neg_cell.negated_values(), c, level, {-1, 0}, 1,
                          up_counters, &up_path),
            end);
  EXPECT_EQ(up_counters.traced, 1);
  ASSERT_EQ(up_path.size(), path.size());
  for (std::size_t i = 1; i < up_path.size(); ++i) {
    EXPECT_NEAR(up_path[i][0], path[i][0], 1e-9) << i;
    EXPECT_NEAR(up_path[i][1], path[i][1], 1e-9) << i;
    EXPECT_GT(-f(up_path[i][0], up_path[i][1]), -f(up_path[i - 1][0], up_path[i - 1][1])) << i;
  }
}

TEST(CertifiedPath, PathLeavingThroughAnEdgeEndsOnIt) {
  // h(U, V) = U + V (2 + B U^2 (3/4 - U)^2) falls towards edge V = 0 from (0.75, 0.1) (level
  // 0.95), and along that edge (h = U) towards corner (0, 0). Below the level: that corner and a
  // chain point at U = 0.5 on the edge (no critical point: the edge is monotone between chain
  // nodes either way), the lower of the two chain nodes around where the path meets the edge
  // (U ~ 0.72). A ridge over U ~ 0.4-0.6 blocks the straight ways to both. The cell field is h
  // composed with each of the three rotations of the reference triangle, so that the path leaves
  // through edge 0, 1 or 2.
  const double B = 2500;
  const Fn h = [B](double U, double V) {
    return U + V * (2 + B * U * U * (0.75 - U) * (0.75 - U));
  };
  const Grad hgrad = [B](double U, double V) -> Vec2 {
    const double b = U * U * (0.75 - U) * (0.75 - U);
    const double db = 2 * U * (0.75 - U) * (0.75 - U) - 2 * U * U * (0.75 - U);
    return {1 + V * B * db, 2 + B * b};
  };
  // (U, V) = rho(u, v) = o + J (u, v), the field g = h o rho: rho maps local edge k onto V = 0
  // and corner k onto (0, 0); start and dir are mapped to (0.75, 0.1) and (0, -1).
  const struct {
    Vec2 o;
    double J[2][2];
    int k;
    Vec2 start, dir;
  } rotations[] = {{{0, 0}, {{1, 0}, {0, 1}}, 0, {0.75, 0.1}, {0, -1}},
                   {{0, 1}, {{0, 1}, {-1, -1}}, 1, {0.15, 0.75}, {1, 0}},
                   {{1, 0}, {{-1, -1}, {1, 0}}, 2, {0.1, 0.15}, {-1, 1}}};
  for (const auto &r : rotations) {
    SCOPED_TRACE(::testing::Message() << "edge " << r.k);
    auto rho = [&](double u, double v) -> Vec2 {
      return {r.o[0] + r.J[0][0] * u + r.J[0][1] * v, r.o[1] + r.J[1][0] * u + r.J[1][1] * v};
    };
    const Fn f = [&](double u, double v) {
      const Vec2 p = rho(u, v);
      return h(p[0], p[1]);
    };
    const Grad grad = [&](double u, double v) -> Vec2 {
      const Vec2 p = rho(u, v), gh = hgrad(p[0], p[1]);
      return {gh[0] * r.J[0][0] + gh[1] * r.J[1][0], gh[0] * r.J[0][1] + gh[1] * r.J[1][1]};
    };
    ASSERT_NEAR(f(r.start[0], r.start[1]), 0.95, 1e-15);
    const BernsteinTriangle g = interpolate(5, f);
    TestCell cell(f);
    const int mid = cell.add_edge_node(r.k, 0.5, f);
    const double level = f(r.start[0], r.start[1]);
    ASSERT_LT(level, 1);
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(cell.values[k] < level, k == r.k) << k;
    ASSERT_NEAR(cell.values[mid], 0.5, 1e-12);
    PathField pf;
    pf.assign(g, false);
    PathCounters counters;
    std::vector<Vec2> path;
    const int m =
        connect_lower(pf, cell.cn, cell.values, r.start, level, r.dir, 1, counters, &path);
    ASSERT_EQ(m, mid);
    EXPECT_EQ(counters.direct, 0);
    EXPECT_EQ(counters.traced, 1);
    ASSERT_EQ(path.size(), 4u); // start, first step, exit point on the edge, chain node
    EXPECT_EQ(path[3], cell.cn.nodes[mid].uv);
    const Vec2 x = path[1], hit = path[2];
    // On the edge, beyond the chain node from corner k.
    const double off_edge[3] = {hit[1], 1 - hit[0] - hit[1], hit[0]};
    EXPECT_NEAR(off_edge[r.k], 0, 1e-12);
    EXPECT_GE(hit[0], -1e-12);
    EXPECT_GE(hit[1], -1e-12);
    EXPECT_LE(hit[0] + hit[1], 1 + 1e-12);
    EXPECT_GT(rho(hit[0], hit[1])[0], 0.5);
    // Where the ray from x along the analytic negative gradient meets that edge.
    const Vec2 gr = grad(x[0], x[1]);
    const Vec2 d = {-gr[0], -gr[1]};
    const double alpha = r.k == 0   ? -x[1] / d[1]
                         : r.k == 1 ? (1 - x[0] - x[1]) / (d[0] + d[1])
                                    : -x[0] / d[0];
    ASSERT_GT(alpha, 0);
    EXPECT_NEAR(hit[0], x[0] + alpha * d[0], 1e-9);
    EXPECT_NEAR(hit[1], x[1] + alpha * d[1], 1e-9);
    expect_strict_descent(f, path, r.start, level);
    // The straight ways from x to the nodes below the level cross the ridge.
    EXPECT_GT(sampled_range(f, x, cell.cn.nodes[r.k].uv).second, level);
    EXPECT_GT(sampled_range(f, x, cell.cn.nodes[mid].uv).second, level);
  }
}

TEST(CertifiedPath, PrefersTargetsAheadOfTheSector) {
  // From the peak along +v the first step ends at (0.3, 0.475); corner 0 is nearer to it than
  // corner 2 and reachable below the level, but lies behind the peak (v < 0.25): corner 2,
  // ahead, comes first.
  const BernsteinTriangle g = interpolate(2, kPeak);
  PathField pf;
  pf.assign(g, false);
  TestCell cell(kPeak);
  const Vec2 c = {0.3, 0.25};
  PathCounters counters;
  std::vector<Vec2> path;
  const int m = connect_lower(pf, cell.cn, cell.values, c, 0.0, {0, 1}, 2, counters, &path);
  ASSERT_EQ(m, 2);
  ASSERT_EQ(path.size(), 3u);
  EXPECT_LT(dist(path[1], cell.cn.nodes[0].uv), dist(path[1], cell.cn.nodes[2].uv));
  EXPECT_TRUE(certify_below(g, path[1], cell.cn.nodes[0].uv, -pf.margin, 0));
  expect_strict_descent(kPeak, path, c, 0.0);
}

} // namespace
} // namespace hoct
