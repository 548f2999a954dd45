// Conversion of equispaced Lagrange node values to Bernstein-Bezier coefficients: fixed matrices
// per degree, computed once (in long double, from the Bernstein-Vandermonde matrix) and cached.
#pragma once

#include <vector>

namespace hoct {

// Row-major (n x n), n = lattice_size(d): c = M * values, both in canonical lattice order.
const std::vector<double> &lagrange_to_bernstein_triangle(int degree);

// Row-major ((d+1) x (d+1)): c = M * values at t = i/d.
const std::vector<double> &lagrange_to_bernstein_1d(int degree);

// Largest degree supported by the conversion tables.
constexpr int kMaxDegree = 20;

} // namespace hoct
