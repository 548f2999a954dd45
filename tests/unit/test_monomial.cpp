// Monomial form: conversion from Bernstein form and Taylor expansions, against direct evaluation.
#include "poly/monomial.hpp"

#include "poly/binomial.hpp"
#include "poly/lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hoct {
namespace {

// sum a[i*(d+1)+j] u^i v^j, term by term (no Horner), and the sum of the terms' magnitudes.
double evaluate(const std::vector<double> &a, int d, double u, double v, double *magnitude) {
  double s = 0, m = 0;
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j) {
      const double t = a[i * (d + 1) + j] * std::pow(u, i) * std::pow(v, j);
      s += t;
      m += std::abs(t);
    }
  if (magnitude)
    *magnitude = m;
  return s;
}

TEST(Monomial, ConversionFromBernsteinCoefficientsMatchesTheTrianglePolynomial) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-1, 1), P(0, 1);
  for (int d = 0; d <= 8; ++d)
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<double> c(lattice_size(d));
      for (double &x : c)
        x = U(rng);
      BernsteinTriangle g(d);
      g.coefficients() = c;
      std::vector<double> mono((d + 1) * (d + 1), 99.0); // stale contents are overwritten
      to_monomial(c.data(), d, mono.data());
      EXPECT_EQ(mono, to_monomial(g));
      for (int k = 0; k < 10; ++k) {
        const double u = P(rng), v = (1 - u) * P(rng);
        EXPECT_NEAR(evaluate(mono, d, u, v, nullptr), g(u, v), 1e-11) << "degree " << d;
      }
    }
}

TEST(Monomial, TaylorExpansionReproducesThePolynomialAroundItsCentre) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int d = 0; d <= 9; ++d)
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> a((d + 1) * (d + 1), 0.0);
      for (int i = 0; i <= d; ++i)
        for (int j = 0; i + j <= d; ++j)
          a[i * (d + 1) + j] = U(rng) * std::pow(4.0, U(rng));
      const double x = 2 * U(rng), y = 2 * U(rng);
      std::vector<double> e((d + 1) * (d + 1), 99.0);
      const double magnitude = taylor_expansion(a.data(), d, x, y, e.data());
      EXPECT_GE(magnitude, std::abs(e[0]));
      // The magnitude bounds the rounding: at least the sum over all Taylor coefficients of the
      // magnitudes of their terms m_ij C(i,a) C(j,b) x^(i-a) y^(j-b), summed term by term here,
      // and at most that times the documented widening max(1, (4d + 4) / 60).
      double terms = 0;
      for (int ta = 0; ta <= d; ++ta)
        for (int tb = 0; ta + tb <= d; ++tb)
          for (int i = ta; i <= d; ++i)
            for (int j = tb; i + j <= d; ++j)
              terms += std::abs(a[i * (d + 1) + j] * binomial(i, ta) * binomial(j, tb) *
                                std::pow(x, i - ta) * std::pow(y, j - tb));
      EXPECT_GE(magnitude, terms * (1 - 1e-12)) << "degree " << d;
      EXPECT_LE(magnitude, terms * std::max(1.0, (4.0 * d + 4) / 60) * (1 + 1e-12) + 1e-300)
          << "degree " << d;
      for (int k = 0; k < 10; ++k) {
        const double s = 0.5 * U(rng), t = 0.5 * U(rng);
        double scale = 0;
        const double direct = evaluate(a, d, x + s, y + t, &scale);
        double shifted = 0;
        for (int i = 0; i <= d; ++i)
          for (int j = 0; i + j <= d; ++j)
            shifted += e[i * (d + 1) + j] * std::pow(s, i) * std::pow(t, j);
        EXPECT_NEAR(shifted, direct, 1e-12 * (scale + magnitude) + 1e-300)
            << "degree " << d << " at (" << x << ", " << y << ")";
      }
    }
}

} // namespace
} // namespace hoct
