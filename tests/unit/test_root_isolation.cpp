// Univariate root isolation against polynomials built from known roots.
#include "poly/root_isolation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace hoct {
namespace {

// Bernstein coefficients of c * prod (t - r_i) on [0, 1], by multiplying linear factors
// (t - r) = (-r)(1 - t) + (1 - r) t in Bernstein form.
BernsteinPoly from_roots(const std::vector<double> &r, double c = 1.0) {
  std::vector<double> p = {c};
  for (double root : r) {
    const int n = static_cast<int>(p.size()) - 1; // degree of p
    std::vector<double> q(n + 2, 0.0);
    // Product of degree-n and degree-1 Bernstein polynomials.
    const double a0 = -root, a1 = 1 - root;
    for (int i = 0; i <= n; ++i) {
      q[i] += p[i] * a0 * (n + 1 - i) / (n + 1.0);
      q[i + 1] += p[i] * a1 * (i + 1) / (n + 1.0);
    }
    p = q;
  }
  return BernsteinPoly(p);
}

TEST(RootIsolation, FindsEveryRootOfRandomPolynomials) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> U(-0.3, 1.3);
  for (int trial = 0; trial < 500; ++trial) {
    const int deg = 1 + static_cast<int>(rng() % 9);
    std::vector<double> r;
    for (int i = 0; i < deg; ++i)
      r.push_back(U(rng));
    const BernsteinPoly p = from_roots(r, 1.0 + trial % 3);
    std::vector<double> inside;
    for (double x : r)
      if (x >= 0 && x <= 1)
        inside.push_back(x);
    std::sort(inside.begin(), inside.end());
    // Skip near-coincident roots here (covered below).
    bool close = false;
    for (std::size_t i = 1; i < inside.size(); ++i)
      close = close || inside[i] - inside[i - 1] < 1e-3;
    if (close)
      continue;
    const auto roots = find_roots(p);
    ASSERT_EQ(roots.size(), inside.size()) << "trial " << trial;
    for (std::size_t i = 0; i < inside.size(); ++i) {
      // Roots 1e-3 apart in a degree-9 polynomial are conditioned to about 1e-11.
      EXPECT_NEAR(roots[i].t, inside[i], 1e-10) << "trial " << trial;
      EXPECT_TRUE(roots[i].simple);
      EXPECT_LE(roots[i].lo, inside[i]);
      EXPECT_GE(roots[i].hi, inside[i]);
    }
  }
}

TEST(RootIsolation, LinearAndQuadraticRootsToFullPrecision) {
  // Degrees 1 and 2 start Newton at the closed-form root: every root in [0, 1] found once, in
  // its interval, to the precision its conditioning allows (one root or two, in the whole
  // interval or in subdivided ones, including roots just inside the ends).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-0.3, 1.3);
  int checked = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int deg = 1 + trial % 2;
    std::vector<double> r;
    for (int i = 0; i < deg; ++i)
      r.push_back(trial % 7 == 0 ? (i == 0 ? 1e-9 : 1 - 1e-9) : U(rng));
    std::sort(r.begin(), r.end());
    if (deg == 2 && r[1] - r[0] < 1e-3)
      continue;
    const double scale = trial % 3 == 0 ? -1e-6 : 2.5;
    const auto roots = find_roots(from_roots(r, scale));
    std::vector<double> inside;
    for (double x : r)
      if (x >= 0 && x <= 1)
        inside.push_back(x);
    ASSERT_EQ(roots.size(), inside.size()) << "trial " << trial;
    for (std::size_t i = 0; i < inside.size(); ++i) {
      EXPECT_NEAR(roots[i].t, inside[i], 1e-12) << "trial " << trial;
      EXPECT_TRUE(roots[i].simple) << "trial " << trial;
      EXPECT_LE(roots[i].lo, roots[i].t);
      EXPECT_GE(roots[i].hi, roots[i].t);
      ++checked;
    }
  }
  EXPECT_GT(checked, 3000);
}

TEST(RootIsolation, EndsMidpointsMultipleAndZero) {
  auto r = find_roots(from_roots({0.0, 0.5, 1.0}));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].t, 0.0);
  EXPECT_EQ(r[1].t, 0.5);
  EXPECT_EQ(r[2].t, 1.0);
  for (const auto &x : r)
    EXPECT_TRUE(x.simple);
  // A double root is reported once, as non-simple.
  r = find_roots(from_roots({0.3, 0.3, 0.8}));
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0].t, 0.3, 1e-6);
  EXPECT_FALSE(r[0].simple);
  EXPECT_TRUE(r[1].simple);
  // A double root exactly at the end.
  r = find_roots(from_roots({0.0, 0.0, 0.6}));
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].t, 0.0);
  EXPECT_FALSE(r[0].simple);
  bool zero = false;
  EXPECT_TRUE(find_roots(BernsteinPoly({0.0, 0.0, 0.0}), {}, &zero).empty());
  EXPECT_TRUE(zero);
  EXPECT_TRUE(find_roots(BernsteinPoly({1.0, -0.1, 2.0})).empty()); // no real root in [0,1]
  // Two roots 1e-6 apart are separated; 1e-9 apart they are one (degenerate) cluster.
  r = find_roots(from_roots({0.4, 0.4 + 1e-6}));
  ASSERT_EQ(r.size(), 2u);
  EXPECT_TRUE(r[0].simple && r[1].simple);
  EXPECT_NEAR(r[1].t - r[0].t, 1e-6, 1e-9);
  r = find_roots(from_roots({0.4, 0.4 + 1e-9}));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].simple);
  EXPECT_NEAR(r[0].t, 0.4, 1e-8);
}

TEST(RootIsolation, SpanFormReusesItsOutputVector) {
  // The allocation-free form (coefficients in, roots into a reused vector): a reused vector gives
  // what a fresh one does, on simple roots, clusters, tangencies and exact zeros at the ends and at
  // subdivision points; the output vector holds stale roots on entry.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-0.2, 1.2);
  std::vector<Root> out(5, Root{0.5, 0.0, 1.0, true, 1});
  std::vector<BernsteinPoly> cases = {
      from_roots({0.0, 0.5, 1.0}), from_roots({0.3, 0.3, 0.8}), from_roots({0.4, 0.4 + 1e-9}),
      BernsteinPoly({1.0, -0.1, 2.0}), BernsteinPoly({0.0, 0.0, 0.0})};
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<double> r;
    for (int k = 0, n = 1 + static_cast<int>(rng() % 8); k < n; ++k)
      r.push_back(trial % 5 == 0 && k == 1 ? r[0] : U(rng)); // some double roots
    cases.push_back(from_roots(r, trial % 2 ? 1.0 : -3.0));
  }
  std::size_t with_roots = 0;
  for (const BernsteinPoly &p : cases) {
    // Into a fresh vector and into `out`, which still holds the previous case's roots.
    bool zero_a = false, zero_b = true;
    std::vector<Root> expected;
    find_roots(p.coefficients(), expected, {}, &zero_a);
    find_roots(p.coefficients(), out, {}, &zero_b);
    EXPECT_EQ(zero_a, zero_b);
    ASSERT_EQ(out.size(), expected.size());
    for (std::size_t k = 0; k < out.size(); ++k) {
      EXPECT_EQ(out[k].t, expected[k].t);
      EXPECT_EQ(out[k].lo, expected[k].lo);
      EXPECT_EQ(out[k].hi, expected[k].hi);
      EXPECT_EQ(out[k].simple, expected[k].simple);
      EXPECT_EQ(out[k].multiplicity, expected[k].multiplicity);
    }
    with_roots += !out.empty();
  }
  EXPECT_GT(with_roots, cases.size() / 2);
  // And against the known roots: every simple root of a random product within 1e-9.
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> r;
    for (int k = 0, n = 1 + static_cast<int>(rng() % 8); k < n; ++k)
      r.push_back(U(rng));
    std::sort(r.begin(), r.end());
    bool close = false;
    for (std::size_t k = 1; k < r.size(); ++k)
      close = close || r[k] - r[k - 1] < 1e-3;
    if (close)
      continue;
    find_roots(from_roots(r).coefficients(), out);
    std::vector<double> inside;
    for (double x : r)
      if (x >= 0 && x <= 1)
        inside.push_back(x);
    ASSERT_EQ(out.size(), inside.size());
    for (std::size_t k = 0; k < out.size(); ++k)
      EXPECT_NEAR(out[k].t, inside[k], 1e-9);
  }
}

} // namespace
} // namespace hoct
