// Monomial form of triangle polynomials, for what Bernstein form does not give cheaply: the
// Taylor expansion at a point, and from it a rigorous enclosure of the range over a small box
// anywhere in the plane (used to bound the Hessian in the Krawczyk test).
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <vector>

namespace hoct {

// Coefficients a[i * (d+1) + j] of u^i v^j (i + j <= d).
std::vector<double> to_monomial(const BernsteinTriangle &p);
// The same from Bernstein coefficients in canonical lattice order, into mono[0 .. (d+1)^2).
void to_monomial(const double *bernstein, int degree, double *mono);

// The monomial coefficients (same layout and degree) of p(B (s, t) + c) as a polynomial in
// (s, t), an affine change of variables, into out[0 .. (d+1)^2); into abs_out those of |p|
// composed with |B| and |c| (every coefficient's absolute value): for each output coefficient the
// sum of the magnitudes of the terms it adds up, which bounds the rounding of `out`.
void compose_affine(const double *mono, int degree, const Mat2 &b, const Vec2 &c, double *out,
                    double *abs_out);

// The Taylor coefficients of p at (x, y), p(x + s, y + t) = sum e[a * (d+1) + b] s^a t^b, into
// e[0 .. (d+1)^2), from p's monomial coefficients. Returns the sum of the magnitudes of all the
// terms added up: 64 eps times it bounds the rounding of every e (and of their sum). With the
// radii of a box, the expansion encloses p's range over it (the Krawczyk test's Hessian).
double taylor_expansion(const double *mono, int degree, double x, double y, double *e);

} // namespace hoct
