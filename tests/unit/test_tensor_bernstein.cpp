// Tensor Bernstein form: conversion from monomial form and subdivision, against direct
// evaluation of the monomials.
#include "poly/tensor_bernstein.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hoct {
namespace {

double monomial_value(const std::vector<double> &a, int d, double u, double v) {
  double s = 0;
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j)
      s += a[i * (d + 1) + j] * std::pow(u, i) * std::pow(v, j);
  return s;
}

std::vector<double> random_monomial(int d, std::mt19937_64 &rng) {
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<double> a((d + 1) * (d + 1), 0.0);
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j)
      a[i * (d + 1) + j] = U(rng);
  return a;
}

TEST(TensorBernstein, FromMonomialMatchesThePolynomialOnTheUnitSquare) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> P(0, 1);
  for (int d = 0; d <= 12; ++d)
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<double> a = random_monomial(d, rng);
      // Entries beyond total degree d are ignored, whatever they hold.
      for (int i = 0; i <= d; ++i)
        for (int j = d - i + 1; j <= d; ++j)
          a[i * (d + 1) + j] = 1e6;
      std::vector<double> t((d + 1) * (d + 1), 99.0);
      TensorBernstein::from_monomial(a.data(), d, t.data());
      const TensorBernstein tb(d, d, t);
      for (int k = 0; k < 10; ++k) {
        const double u = P(rng), v = P(rng);
        EXPECT_NEAR(tb(u, v), monomial_value(a, d, u, v), 1e-12 * std::pow(3.0, d))
            << "degree " << d;
      }
    }
}

TEST(TensorBernstein, QuartersAndHalvesAgreeWithTheParentBox) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> P(0, 1);
  for (int d = 1; d <= 10; ++d) {
    const std::vector<double> a = random_monomial(d, rng);
    std::vector<double> t((d + 1) * (d + 1));
    TensorBernstein::from_monomial(a.data(), d, t.data());
    const std::size_t n = t.size();
    std::vector<double> out(4 * n);
    double *q[4] = {&out[0], &out[n], &out[2 * n], &out[3 * n]};
    TensorBernstein::split_quarters(t.data(), d, d, q);
    for (int k = 0; k < 4; ++k) {
      const TensorBernstein child(d, d, std::vector<double>(q[k], q[k] + n));
      const double u0 = 0.5 * (k & 1), v0 = 0.5 * (k >> 1);
      for (int r = 0; r < 5; ++r) {
        const double s = P(rng), w = P(rng);
        EXPECT_NEAR(child(s, w), monomial_value(a, d, u0 + 0.5 * s, v0 + 0.5 * w), 1e-11)
            << "degree " << d << " quarter " << k;
      }
    }
    for (bool along_s : {true, false}) {
      double *h[2] = {&out[0], &out[n]};
      TensorBernstein::split_halves(t.data(), d, d, along_s, h);
      for (int k = 0; k < 2; ++k) {
        const TensorBernstein half(d, d, std::vector<double>(h[k], h[k] + n));
        for (int r = 0; r < 5; ++r) {
          const double s = P(rng), w = P(rng);
          const double u = along_s ? 0.5 * (k + s) : s, v = along_s ? w : 0.5 * (k + w);
          EXPECT_NEAR(half(s, w), monomial_value(a, d, u, v), 1e-11)
              << "degree " << d << (along_s ? " along s" : " along t");
        }
      }
    }
  }
}

} // namespace
} // namespace hoct
