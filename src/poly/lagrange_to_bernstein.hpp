// Conversion of equispaced Lagrange node values to Bernstein-Bezier coefficients: fixed matrices
// per degree, computed once (in long double, from the Bernstein-Vandermonde matrix) and cached.
#pragma once

#include <vector>

namespace hoct {

// Row-major (n x n), n = lattice_size(d): c = M * values, both in canonical lattice order.
const std::vector<double> &lagrange_to_bernstein_triangle(int degree);

// Row-major ((d+1) x (d+1)): c = M * values at t = i/d.
const std::vector<double> &lagrange_to_bernstein_1d(int degree);

// The conversion's infinity norm (largest absolute row sum of the triangle matrix): a change
// of e in every node value moves every Bernstein coefficient, hence the field, by at most this
// times e. 1 for degree 1; grows with the degree (equispaced nodes).
double lagrange_to_bernstein_norm(int degree);

// Largest degree supported by the conversion tables.
constexpr int kMaxDegree = 20;

} // namespace hoct
