// A certified bound on how far a triangle polynomial is from its linear interpolant on a
// sub-triangle: what a cell's piecewise-linear stand-in (the degenerate-cell fallback) may be off
// by. For x in the sub-triangle with barycentrics l_i of its corners v_i, Taylor's theorem at x
// gives L(x) - p(x) = 1/2 sum_i l_i D2p(xi_i)(v_i - x, v_i - x), and sum_i l_i |v_i - x|^2 =
// sum_i l_i |v_i - c|^2 - |x - c|^2 <= R^2 for the centre c and radius R of the smallest disk
// holding the sub-triangle. So |p - L| <= M R^2 / 2, M a bound on the Hessian's norm over the
// cell: its three second derivatives are Bernstein polynomials of degree d - 2, bounded by their
// coefficients (S. Waldron, SIAM J. Numer. Anal. 35, 1998, shows the constant is sharp).
#pragma once

#include "poly/bernstein_triangle.hpp"
#include "util/vec.hpp"

namespace hoct {

class InterpolationError {
public:
  // The Hessian bound of p over the reference triangle, once for all its sub-triangles.
  explicit InterpolationError(const BernsteinTriangle &p);

  // An upper bound on max |p - L| over the triangle a, b, c of the reference triangle (L: the
  // linear interpolant of p at a, b, c), plus the rounding of p's values at a, b, c.
  double on(const Vec2 &a, const Vec2 &b, const Vec2 &c) const;

  // The bound on the Hessian's (spectral) norm over the cell.
  double hessian_bound() const { return hessian_; }

private:
  double hessian_ = 0;
  double rounding_ = 0;
};

// The squared radius of the smallest disk containing the triangle a, b, c.
double enclosing_radius_squared(const Vec2 &a, const Vec2 &b, const Vec2 &c);

} // namespace hoct
