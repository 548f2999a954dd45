// The fallback stand-in's slack (poly/interpolation_error.hpp) against brute force: on random
// polynomials of degrees 1-8 and random sub-triangles, the sampled |p - L| never exceeds the
// bound; for a quadratic with a known Hessian the bound is attained (Waldron's constant is
// sharp), and the enclosing disk is right for acute, right and obtuse triangles.
#include "poly/interpolation_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hoct {
namespace {

TEST(InterpolationError, SmallestEnclosingDisk) {
  // Right isosceles (legs 1): the hypotenuse is a diameter.
  EXPECT_DOUBLE_EQ(enclosing_radius_squared({0, 0}, {1, 0}, {0, 1}), 0.5);
  // Obtuse: half the longest side.
  EXPECT_DOUBLE_EQ(enclosing_radius_squared({0, 0}, {1, 0}, {0.5, 0.1}), 0.25);
  // Equilateral (side 1): the circumradius 1 / sqrt(3).
  EXPECT_NEAR(enclosing_radius_squared({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}), 1.0 / 3, 1e-15);
}

TEST(InterpolationError, BoundsTheSampledErrorOnRandomPolynomials) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1, 1), P(0, 1);
  for (int d = 1; d <= 8; ++d)
    for (int trial = 0; trial < 20; ++trial) {
      BernsteinTriangle p(d);
      for (double &c : p.coefficients())
        c = U(rng);
      const InterpolationError bound(p);
      // A random sub-triangle of the reference triangle.
      auto point = [&] {
        double u = P(rng), v = P(rng);
        if (u + v > 1)
          u = 1 - u, v = 1 - v;
        return Vec2{u, v};
      };
      const Vec2 a = point(), b = point(), c = point();
      const double pa = p(a[0], a[1]), pb = p(b[0], b[1]), pc = p(c[0], c[1]);
      double sampled = 0;
      for (int i = 0; i <= 40; ++i)
        for (int j = 0; i + j <= 40; ++j) {
          const double s = i / 40.0, t = j / 40.0, r = 1 - s - t;
          const double x = r * a[0] + s * b[0] + t * c[0], y = r * a[1] + s * b[1] + t * c[1];
          sampled = std::max(sampled, std::abs(p(x, y) - (r * pa + s * pb + t * pc)));
        }
      EXPECT_LE(sampled, bound.on(a, b, c)) << "degree " << d << " trial " << trial;
      if (d == 1) {
        EXPECT_LT(bound.on(a, b, c), 1e-14);
      }
    }
}

TEST(InterpolationError, AttainedByAQuadratic) {
  // p = -(u - v)^2: Hessian [[-2, 2], [2, -2]], norm 4; on the sub-triangle (0,0), (1/4,0),
  // (0,1/4) (R^2 = 1/32) the bound 4 / 32 / 2 = 1/16 is the error at (1/8, 1/8).
  BernsteinTriangle p(2);
  // Bernstein coefficients of -(u - v)^2 (lattice order (a, b) = u-, v-exponents): 0 at the
  // corner (0,0), -1 at (1,0) and (0,1); the mixed ones from the polar form.
  p.coefficients() = {0, 0, -1, 0, 1, -1};
  ASSERT_NEAR(p(0.3, 0.1), -0.04, 1e-15);
  const InterpolationError bound(p);
  EXPECT_NEAR(bound.hessian_bound(), 4, 1e-12);
  EXPECT_NEAR(bound.on({0, 0}, {0.25, 0}, {0, 0.25}), 1.0 / 16, 1e-12);
  // The actual error there: p(1/8, 1/8) = 0 against the interpolant's -1/16.
  EXPECT_NEAR(p(0.125, 0.125) - (-1.0 / 16), 1.0 / 16, 1e-15);
}

} // namespace
} // namespace hoct
