// Bivariate polynomials of total degree d in Bernstein-Bezier form on the reference triangle
// P0 = (0,0), P1 = (1,0), P2 = (0,1):
//   g(u, v) = sum_{a+b<=d} c[a,b] * d!/((d-a-b)! a! b!) * (1-u-v)^(d-a-b) u^a v^b,
// coefficients in canonical lattice order (poly/lattice.hpp). Coefficients enclose the range over
// the triangle; the coefficients with b = 0 (resp. a + b = d, a = 0) are those of edge 0 (resp.
// 1, 2).
#pragma once

#include "poly/bernstein_univariate.hpp"
#include "poly/lattice.hpp"
#include "util/vec.hpp"

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace hoct {

using Mat2 = std::array<std::array<double, 2>, 2>;

class BernsteinTriangle {
public:
  BernsteinTriangle() = default;
  BernsteinTriangle(int degree, std::vector<double> coefficients);
  // The zero polynomial of the given degree.
  explicit BernsteinTriangle(int degree);

  int degree() const { return d_; }
  const std::vector<double> &coefficients() const { return c_; }
  std::vector<double> &coefficients() { return c_; }
  // Becomes the polynomial of the given degree and coefficients (lattice order), reusing this
  // one's storage (for per-cell scratch polynomials).
  void assign(int degree, std::span<const double> coefficients);
  double coefficient(int a, int b) const { return c_[lattice_index(d_, a, b)]; }

  // Value at (u, v) by de Casteljau.
  double operator()(double u, double v) const;
  // Partial derivatives as polynomials of degree d-1 (degree 0 zero polynomial for d = 0).
  BernsteinTriangle du() const;
  BernsteinTriangle dv() const;
  // The derivative along e (reference coordinates): e[0] du + e[1] dv, of degree d - 1.
  BernsteinTriangle along(const Vec2 &e) const;
  Vec2 gradient(double u, double v) const;
  // [[g_uu, g_uv], [g_uv, g_vv]].
  Mat2 hessian(double u, double v) const;
  // Value, gradient and Hessian at (u, v) in one de Casteljau pass, without allocating (for
  // degrees up to 12): the last two steps' coefficients give the derivatives.
  struct Jet {
    double value;
    Vec2 gradient;
    Mat2 hessian;
  };
  Jet jet(double u, double v) const;
  // The same for coefficients (lattice order) of the given degree held elsewhere.
  static Jet jet_of(std::span<const double> coefficients, int degree, double u, double v);

  // Restriction to edge k (0: P0->P1, 1: P1->P2, 2: P2->P0), parameter t from the first corner.
  BernsteinPoly edge(int k) const;
  // Replaces the coefficients of edge k with those of p (same degree), parameterised as edge(k).
  void set_edge(int k, const BernsteinPoly &p);
  // Restriction to the segment p -> q (points in (u, v) coordinates, anywhere in the plane):
  // s(t) = g(p + t (q - p)), t in [0, 1], by blossoming.
  BernsteinPoly restrict_to_segment(const Vec2 &p, const Vec2 &q) const;
  // The same into out[0..degree()] without allocating (for degrees up to 12; heap beyond).
  void restrict_to_segment(const Vec2 &p, const Vec2 &q, double *out) const;

  // Same polynomial in degree `degree` >= d.
  BernsteinTriangle elevated(int degree) const;
  // Product of two polynomials (degree d1 + d2).
  BernsteinTriangle operator*(const BernsteinTriangle &other) const;
  // Certified enclosure of the range over the triangle: min and max coefficient.
  std::pair<double, double> bounds() const;
  // True if all coefficients are equal (the polynomial is constant).
  bool is_constant() const;
  // The largest Bernstein coefficient of du and dv in magnitude, d |c[a+1,b] - c[a,b]| or
  // d |c[a,b+1] - c[a,b]|: the scale against which the gradient's rounding is judged.
  double gradient_scale() const;

private:
  int d_ = 0;
  std::vector<double> c_;
};

// Barycentric coordinates (l0, l1, l2) of (u, v).
inline std::array<double, 3> barycentric(double u, double v) { return {1.0 - u - v, u, v}; }

// Triangle Bernstein coefficients from equispaced Lagrange node values (canonical lattice order).
BernsteinTriangle bernstein_from_lattice_values(const double *values, int degree);
// The same into out[0 .. lattice_size(degree)) without allocating.
void bernstein_from_lattice_values(const double *values, int degree, double *out);

} // namespace hoct
