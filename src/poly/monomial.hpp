// Monomial form of triangle polynomials, for what Bernstein form does not give cheaply: the
// Taylor expansion at a point, and from it a rigorous enclosure of the range over a small box
// anywhere in the plane (used to bound the Hessian in the Krawczyk test).
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <utility>
#include <vector>

namespace hoct {

// Coefficients a[i * (d+1) + j] of u^i v^j (i + j <= d).
std::vector<double> to_monomial(const BernsteinTriangle &p);

// The monomial coefficients (same layout and degree) of p(B (s, t) + c) as a polynomial in
// (s, t), an affine change of variables, into out[0 .. (d+1)^2); into abs_out those of |p|
// composed with |B| and |c| (every coefficient's absolute value): for each output coefficient the
// sum of the magnitudes of the terms it adds up, which bounds the rounding of `out`.
void compose_affine(const double *mono, int degree, const Mat2 &b, const Vec2 &c, double *out,
                    double *abs_out);

// Enclosure [lo, hi] of p over the box |u - x| <= rx, |v - y| <= ry, from the Taylor expansion
// at (x, y), given p's monomial coefficients and degree. Inflated for rounding.
std::pair<double, double> monomial_range(const std::vector<double> &mono, int degree, double x,
                                         double y, double rx, double ry);

} // namespace hoct
