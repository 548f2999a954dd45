// Bernstein forms of test fields, shared by the tests of the cell computations.
#pragma once

#include "poly/bernstein_triangle.hpp"
#include "poly/lattice.hpp"

#include <functional>
#include <vector>

namespace hoct::testing {

// The Bernstein form of a polynomial of total degree <= d given as a function, through its
// values at the equispaced lattice (the library's Lagrange-to-Bernstein conversion).
inline BernsteinTriangle interpolate(int d, const std::function<double(double, double)> &f) {
  std::vector<double> vals(static_cast<std::size_t>(lattice_size(d)));
  for (int i = 0; i < lattice_size(d); ++i) {
    const auto p = lattice_point(d, i);
    vals[static_cast<std::size_t>(i)] =
        f(p[0] / static_cast<double>(d), p[1] / static_cast<double>(d));
  }
  return bernstein_from_lattice_values(vals.data(), d);
}

// The exact Bernstein form of A(u) + C(v) from the univariate Bernstein coefficients a of A and
// c of C (both of degree d): on the triangle the coefficient (i, j) is a[i] + c[j].
inline BernsteinTriangle separable(const std::vector<double> &a, const std::vector<double> &c) {
  const int d = static_cast<int>(a.size()) - 1;
  std::vector<double> coef(static_cast<std::size_t>(lattice_size(d)));
  for (int j = 0; j <= d; ++j)
    for (int i = 0; i + j <= d; ++i)
      coef[static_cast<std::size_t>(lattice_index(d, i, j))] = a[i] + c[j];
  return BernsteinTriangle(d, coef);
}

} // namespace hoct::testing
