// A certified bound on how far a triangle polynomial is from its linear interpolant on a
// sub-triangle: what a cell's piecewise-linear stand-in (the degenerate-cell fallback) may be off
// by. The polynomial restricted to the sub-triangle is again a polynomial of degree d in its
// barycentric coordinates; the linear interpolant of its corner values, raised to degree d, has
// the Bernstein coefficients L(domain point). Their differences bound |p - L| on the sub-triangle
// (Bernstein polynomials are a partition of unity).
#pragma once

#include "poly/bernstein_triangle.hpp"
#include "util/vec.hpp"

#include <vector>

namespace hoct {

class InterpolationError {
public:
  // For the sub-triangles of one polynomial (the conversion table and the rounding margin are
  // taken once).
  explicit InterpolationError(const BernsteinTriangle &p);

  // max |p - L| over the triangle a, b, c of the reference triangle (L: the linear interpolant
  // of p at a, b, c), bounded from above: the differences of the Bernstein coefficients, plus
  // the rounding of computing them.
  double on(const Vec2 &a, const Vec2 &b, const Vec2 &c);

private:
  const BernsteinTriangle &p_;
  const std::vector<double> *conversion_ = nullptr;
  double rounding_ = 0; // the margin for the coefficients' magnitude, per unit of eps
  std::vector<double> samples_, linear_;
};

} // namespace hoct
