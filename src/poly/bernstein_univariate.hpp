// Univariate polynomials in Bernstein form on [0, 1]:
//   p(t) = sum_{i=0..n} b_i C(n,i) t^i (1-t)^(n-i).
// The restriction of a triangle polynomial to an edge or a segment is one of these; its
// coefficients enclose its range on [0, 1] (convex hull property).
#pragma once

#include <span>
#include <utility>
#include <vector>

namespace hoct {

// Value at t of the polynomial with Bernstein coefficients c (de Casteljau; stable for t in
// [0, 1]); 0 for no coefficients. BernsteinPoly::operator() is this.
double bernstein_value(std::span<const double> c, double t);
// The derivative's coefficients n (c[i+1] - c[i]), i < n = c.size() - 1, into out[0 .. n)
// (nothing for n = 0). BernsteinPoly::derivative is this.
void bernstein_derivative(std::span<const double> c, double *out);
// Sign changes of the coefficient sequence c (zeros skipped). BernsteinPoly::sign_changes is this.
int bernstein_sign_changes(std::span<const double> c);

class BernsteinPoly {
public:
  BernsteinPoly() = default;
  explicit BernsteinPoly(std::vector<double> coefficients) : c_(std::move(coefficients)) {}

  int degree() const { return static_cast<int>(c_.size()) - 1; }
  const std::vector<double> &coefficients() const { return c_; }
  std::vector<double> &coefficients() { return c_; }
  double operator[](int i) const { return c_[i]; }

  // Value at t (de Casteljau; stable for t in [0, 1]).
  double operator()(double t) const;
  // Derivative (degree n-1; the zero polynomial of degree 0 for n = 0).
  BernsteinPoly derivative() const;
  // The same polynomial run backwards: q(t) = p(1 - t).
  BernsteinPoly reversed() const;
  // Degree elevated to `degree` (>= current degree); same polynomial.
  BernsteinPoly elevated(int degree) const;
  // The polynomial on [a, b] reparameterised to [0, 1]: q(s) = p(a + s (b - a)).
  BernsteinPoly subinterval(double a, double b) const;
  // Splits at t into the pieces on [0, t] and [t, 1], each reparameterised to [0, 1].
  std::pair<BernsteinPoly, BernsteinPoly> split(double t) const;
  // Certified enclosure of the range on [0, 1]: min and max coefficient.
  std::pair<double, double> bounds() const;
  // Number of sign changes of the coefficient sequence (zeros skipped): an upper bound on the
  // number of roots in (0, 1) (Descartes' rule of signs in Bernstein form).
  int sign_changes() const;

private:
  std::vector<double> c_;
};

// 1D equispaced Lagrange values (at t = i/n, i = 0..n) to Bernstein coefficients.
BernsteinPoly bernstein_from_equispaced(const double *values, int degree);
// The same into out[0 .. degree] (no allocation).
void bernstein_from_equispaced(const double *values, int degree, double *out);

} // namespace hoct
