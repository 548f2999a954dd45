// Polynomials in tensor-product Bernstein form of bidegree (m, n) on a box [u0,u1] x [v0,v1]:
//   p(u, v) = sum_{i,j} b[i][j] B_i^m(s) B_j^n(t),  s = (u-u0)/(u1-u0), t = (v-v0)/(v1-v0).
// A triangle polynomial of total degree m is one of bidegree (m, m) on the unit square; boxes
// subdivide by univariate de Casteljau along each direction, and the coefficients enclose the
// range over the box. Used to isolate the zeros of the gradient.
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <array>
#include <utility>
#include <vector>

namespace hoct {

class TensorBernstein {
public:
  TensorBernstein() = default;
  TensorBernstein(int m, int n, std::vector<double> coefficients); // b[i][j] at i * (n+1) + j

  // The triangle polynomial as bidegree (d, d) on [0,1]^2.
  static TensorBernstein from_triangle(const BernsteinTriangle &p);
  // The same from monomial coefficients mono[a * (d+1) + b] of u^a v^b (a + b <= d): writes the
  // (d+1)^2 tensor coefficients to out (no allocation).
  static void from_monomial(const double *mono, int d, double *out);

  int degree_u() const { return m_; }
  int degree_v() const { return n_; }
  double coefficient(int i, int j) const { return b_[i * (n_ + 1) + j]; }
  const std::vector<double> &coefficients() const { return b_; }

  // Value at local box parameters (s, t) in [0,1]^2.
  double operator()(double s, double t) const;
  // Derivatives with respect to the local parameters s and t.
  TensorBernstein ds() const;
  TensorBernstein dt() const;
  // The four quarter boxes: (s in [0,.5] or [.5,1]) x (t likewise), order (0,0),(1,0),(0,1),(1,1).
  std::array<TensorBernstein, 4> quarters() const;
  // The same on raw coefficient arrays of bidegree (m, n) (no allocation): q[k] receives the
  // (m+1)(n+1) coefficients of quarter k; the four outputs must not overlap b.
  static void split_quarters(const double *b, int m, int n, double *const q[4]);
  // The two halves along s (along_s) or t: h[0] the lower, h[1] the upper half; the outputs
  // must not overlap b.
  static void split_halves(const double *b, int m, int n, bool along_s, double *const h[2]);
  std::pair<double, double> bounds() const;
  // True if every coefficient is > 0, or every one is < 0: no zero in the box.
  bool excludes_zero() const;

private:
  int m_ = 0, n_ = 0;
  std::vector<double> b_;
};

} // namespace hoct
