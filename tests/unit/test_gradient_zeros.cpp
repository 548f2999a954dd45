// Interior critical points of single cells against closed-form answers and an independent
// brute-force Newton search.
#include "poly/gradient_zeros.hpp"
#include "poly/lattice.hpp"
#include "test_functions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

namespace hoct {
namespace {

BernsteinTriangle from_function(int d, const std::function<double(double, double)> &f) {
  std::vector<double> vals(lattice_size(d));
  for (int i = 0; i < lattice_size(d); ++i) {
    const auto p = lattice_point(d, i);
    vals[i] = f(static_cast<double>(p[0]) / d, static_cast<double>(p[1]) / d);
  }
  return bernstein_from_lattice_values(vals.data(), d);
}

using testing::antiderivative_of_roots;
using testing::horner;

class GradientZerosDegree : public ::testing::TestWithParam<int> {};

TEST_P(GradientZerosDegree, SeparableFieldsHaveTheKnownGrid) {
  // g = A(u) + B(v): critical points exactly at (r_i, s_j), r_i roots of A', s_j of B'.
  const int d = GetParam();
  std::mt19937_64 rng(100 + d);
  std::uniform_real_distribution<double> U(0.02, 0.98);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<double> r, s;
    for (int i = 0; i < d - 1; ++i) {
      r.push_back(U(rng));
      s.push_back(U(rng));
    }
    auto well_separated = [](std::vector<double> x) {
      std::sort(x.begin(), x.end());
      for (std::size_t i = 1; i < x.size(); ++i)
        if (x[i] - x[i - 1] < 0.02)
          return false;
      return true;
    };
    if (!well_separated(r) || !well_separated(s))
      continue;
    const auto A = antiderivative_of_roots(r), B = antiderivative_of_roots(s);
    const BernsteinTriangle g =
        from_function(d, [&](double u, double v) { return horner(A, u) + 0.7 * horner(B, v); });
    std::vector<std::array<double, 2>> expected;
    for (double x : r)
      for (double y : s)
        if (x + y < 1 - 1e-3)
          expected.push_back({x, y});
        else if (x + y <= 1 + 1e-3)
          goto skip; // too close to the hypotenuse for an exact count
    {
      const GradientZeros z = find_gradient_zeros(g);
      EXPECT_FALSE(z.budget_exhausted);
      ASSERT_EQ(z.zeros.size(), expected.size()) << "d=" << d << " trial " << trial;
      for (const auto &e : expected) {
        bool hit = false;
        for (const auto &f : z.zeros)
          if (std::abs(f.u - e[0]) < 1e-8 && std::abs(f.v - e[1]) < 1e-8) {
            hit = true;
            EXPECT_TRUE(f.certified);
          }
        EXPECT_TRUE(hit) << "missing (" << e[0] << ", " << e[1] << ") d=" << d;
      }
    }
  skip:;
  }
}

TEST_P(GradientZerosDegree, RandomPolynomialsAgreeWithBruteForceNewton) {
  const int d = GetParam();
  std::mt19937_64 rng(200 + d);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<double> c(lattice_size(d));
    for (double &x : c)
      x = U(rng);
    const BernsteinTriangle g(d, c);
    const BernsteinTriangle gu = g.du(), gv = g.dv(), guu = gu.du(), guv = gu.dv(), gvv = gv.dv();
    // Independent: Newton from a 60 x 60 grid of starts, deduplicated.
    std::vector<std::array<double, 2>> brute;
    for (int i = 0; i <= 60; ++i)
      for (int j = 0; i + j <= 60; ++j) {
        double u = i / 60.0, v = j / 60.0;
        bool ok = false;
        for (int it = 0; it < 60; ++it) {
          const double fu = gu(u, v), fv = gv(u, v);
          const double a = guu(u, v), b = guv(u, v), cc = gvv(u, v);
          const double det = a * cc - b * b;
          if (det == 0)
            break;
          const double du = (cc * fu - b * fv) / det, dv = (a * fv - b * fu) / det;
          u -= du;
          v -= dv;
          if (std::abs(u) > 5 || std::abs(v) > 5)
            break;
          if (std::abs(du) + std::abs(dv) < 1e-14) {
            ok = true;
            break;
          }
        }
        if (!ok || u < 1e-6 || v < 1e-6 || u + v > 1 - 1e-6)
          continue;
        bool dup = false;
        for (const auto &b : brute)
          dup = dup || (std::abs(b[0] - u) < 1e-7 && std::abs(b[1] - v) < 1e-7);
        if (!dup)
          brute.push_back({u, v});
      }
    const GradientZeros z = find_gradient_zeros(g);
    int interior = 0;
    for (const auto &f : z.zeros)
      interior += !f.near_boundary;
    // Every brute-force zero is found; the certified search may find more (brute force can miss
    // basins), never fewer.
    for (const auto &b : brute) {
      bool hit = false;
      for (const auto &f : z.zeros)
        hit = hit || (std::abs(f.u - b[0]) < 1e-8 && std::abs(f.v - b[1]) < 1e-8);
      EXPECT_TRUE(hit) << "d=" << d << " trial " << trial << ": missed (" << b[0] << ", " << b[1]
                       << ")";
    }
    EXPECT_GE(interior, static_cast<int>(brute.size()));
    EXPECT_LE(static_cast<int>(z.zeros.size()), (d - 1) * (d - 1));
    for (const auto &f : z.zeros) {
      EXPECT_NEAR(gu(f.u, f.v), 0.0, 1e-9);
      EXPECT_NEAR(gv(f.u, f.v), 0.0, 1e-9);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Degrees2To8, GradientZerosDegree, ::testing::Range(2, 9));

TEST(GradientScreen, CombinedComponentsExcludeWhatSingleOnesCannot) {
  // A bowl centred outside the triangle, beyond its hypotenuse: both gradient components change
  // sign on the triangle, their combination along the mean gradient does not.
  const BernsteinTriangle outside = from_function(
      3, [](double u, double v) { return (u - 0.6) * (u - 0.6) + (v - 0.6) * (v - 0.6); });
  EXPECT_EQ(screen_gradient(outside.coefficients(), 3, 1e-12).verdict, GradientScreen::kNoZero);
  EXPECT_TRUE(find_gradient_zeros(outside).zeros.empty());
  const BernsteinTriangle inside = from_function(
      3, [](double u, double v) { return (u - 0.3) * (u - 0.3) + (v - 0.3) * (v - 0.3); });
  EXPECT_EQ(screen_gradient(inside.coefficients(), 3, 1e-12).verdict, GradientScreen::kSearch);
  ASSERT_EQ(find_gradient_zeros(inside).zeros.size(), 1u);
}

TEST(GradientScreen, NeverDiscardsACellWithAGradientZero) {
  // Bowls and saddles centred near the triangle's boundary (inside and out), perturbed at
  // random, degrees 2 to 8: whenever the screen says "no zero", an independent Newton search
  // from a dense grid of starts finds none in the closed triangle.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  int discarded = 0;
  for (int d = 2; d <= 8; ++d)
    for (int trial = 0; trial < 60; ++trial) {
      const double cu = 0.5 + 0.6 * U(rng), cv = 0.5 + 0.6 * U(rng), sign = trial % 2 ? 1 : -1;
      std::vector<double> noise(lattice_size(d));
      for (double &x : noise)
        x = 0.02 * U(rng);
      BernsteinTriangle g = from_function(d, [&](double u, double v) {
        return (u - cu) * (u - cu) + sign * (v - cv) * (v - cv) + 0.3 * (u - cu) * (v - cv);
      });
      for (std::size_t i = 0; i < noise.size(); ++i)
        g.coefficients()[i] += noise[i];
      if (screen_gradient(g.coefficients(), d, 1e-12).verdict != GradientScreen::kNoZero)
        continue;
      ++discarded;
      const BernsteinTriangle gu = g.du(), gv = g.dv(), guu = gu.du(), guv = gu.dv(), gvv = gv.dv();
      for (int i = 0; i <= 30; ++i)
        for (int j = 0; i + j <= 30; ++j) {
          double u = i / 30.0, v = j / 30.0;
          for (int it = 0; it < 50; ++it) {
            const double fu = gu(u, v), fv = gv(u, v), a = guu(u, v), b = guv(u, v), c = gvv(u, v),
                         det = a * c - b * b;
            if (det == 0 || std::abs(u) > 5 || std::abs(v) > 5)
              break;
            u -= (c * fu - b * fv) / det;
            v -= (a * fv - b * fu) / det;
          }
          const bool zero = std::abs(gu(u, v)) + std::abs(gv(u, v)) < 1e-10;
          EXPECT_FALSE(zero && u >= -1e-9 && v >= -1e-9 && u + v <= 1 + 1e-9)
              << "d=" << d << " trial " << trial << ": zero at (" << u << ", " << v << ")";
        }
    }
  EXPECT_GT(discarded, 50); // the screen does discard cells here
}

TEST(GradientZeros, DegenerateCasesAreReportedNotDropped) {
  // A ridge: g = -(u - 0.3)^2, critical along the whole line u = 0.3.
  const GradientZeros ridge = find_gradient_zeros(
      from_function(2, [](double u, double) { return -(u - 0.3) * (u - 0.3); }));
  EXPECT_TRUE(ridge.budget_exhausted || ridge.unresolved > 0);
  // A degenerate (singular Hessian) isolated critical point: g = (u-0.3)^2 + (v-0.3)^4.
  const GradientZeros flat = find_gradient_zeros(from_function(
      4, [](double u, double v) { return (u - 0.3) * (u - 0.3) + std::pow(v - 0.3, 4); }));
  ASSERT_FALSE(flat.zeros.empty());
  EXPECT_FALSE(flat.zeros[0].certified);
  EXPECT_NEAR(flat.zeros[0].u, 0.3, 1e-6);
  EXPECT_NEAR(flat.zeros[0].v, 0.3, 1e-3);
  // Constant and linear cells.
  EXPECT_TRUE(find_gradient_zeros(from_function(3, [](double, double) { return 2.0; })).constant);
  const GradientZeros lin =
      find_gradient_zeros(from_function(3, [](double u, double v) { return u - 2 * v; }));
  EXPECT_FALSE(lin.constant);
  EXPECT_TRUE(lin.zeros.empty());
  // A critical point exactly on a subdivision line (u = v = 0.25) is still certified.
  const GradientZeros sym = find_gradient_zeros(from_function(
      2, [](double u, double v) { return (u - 0.25) * (u - 0.25) + 2 * (v - 0.25) * (v - 0.25); }));
  ASSERT_EQ(sym.zeros.size(), 1u);
  EXPECT_TRUE(sym.zeros[0].certified);
  EXPECT_NEAR(sym.zeros[0].u, 0.25, 1e-14);
  // On the boundary: flagged.
  const GradientZeros edge = find_gradient_zeros(
      from_function(2, [](double u, double v) { return (u - 0.5) * (u - 0.5) - v * v; }));
  ASSERT_EQ(edge.zeros.size(), 1u);
  EXPECT_TRUE(edge.zeros[0].near_boundary);
}

} // namespace
} // namespace hoct
