#include "cell/critical_edges.hpp"

#include "poly/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {
namespace {

// The row of lattice point (a, b) counted from local edge k (0: on the edge): the index of the
// barycentric coordinate that vanishes there.
int row(int d, int k, int a, int b) { return k == 0 ? b : (k == 1 ? d - a - b : a); }

// Lattice point (a, b) of degree d moved two rows towards edge k, in degree d - 2.
int q_index(int d, int k, int a, int b) {
  return k == 0 ? lattice_index(d - 2, a, b - 2)
                : (k == 1 ? lattice_index(d - 2, a, b) : lattice_index(d - 2, a - 2, b));
}

// The reference gradient of the barycentric coordinate that vanishes on local edge k.
Vec2 coordinate_gradient(int k) {
  return k == 0 ? Vec2{0, 1} : (k == 1 ? Vec2{-1, -1} : Vec2{1, 0});
}

} // namespace

std::optional<CriticalEdge> critical_edge(const BernsteinTriangle &g, int k, double precision) {
  const int d = g.degree();
  if (d < 2)
    return std::nullopt; // a linear cell: constant along an edge means a level edge or none
  // The value at the edge's first corner (corner k).
  const double c =
      k == 0 ? g.coefficient(0, 0) : (k == 1 ? g.coefficient(d, 0) : g.coefficient(0, d));
  const double near = 2 * precision;
  double slack = 0, lo = INFINITY, hi = -INFINITY;
  BernsteinTriangle q(d - 2);
  for (int b = 0; b <= d; ++b)
    for (int a = 0; a + b <= d; ++a) {
      const double x = g.coefficient(a, b) - c;
      const int r = row(d, k, a, b);
      if (r <= 1) {
        slack = std::max(slack, std::abs(x));
        continue;
      }
      lo = std::min(lo, x);
      hi = std::max(hi, x);
      q.coefficients()[q_index(d, k, a, b)] = x * d * (d - 1) / (r * (r - 1));
    }
  if (!(slack <= near))
    return std::nullopt;
  int side = 0;
  if (lo > near)
    side = 1;
  else if (hi < -near)
    side = -1;
  else
    return std::nullopt;
  // h . grad w = 2 q |grad w|^2 + w (grad q . grad w), of degree d - 2.
  const Vec2 gw = coordinate_gradient(k);
  BernsteinTriangle h = q;
  for (double &x : h.coefficients())
    x *= 2 * (gw[0] * gw[0] + gw[1] * gw[1]);
  if (d >= 3) {
    BernsteinTriangle dq = q.du();
    const BernsteinTriangle dqv = q.dv();
    for (std::size_t i = 0; i < dq.coefficients().size(); ++i)
      dq.coefficients()[i] = gw[0] * dq.coefficients()[i] + gw[1] * dqv.coefficients()[i];
    // w in degree 1: v (k = 0), 1 - u - v (k = 1: the corner (0, 0)), u (k = 2).
    BernsteinTriangle w(1);
    w.coefficients()[lattice_index(1, k == 2 ? 1 : 0, k == 0 ? 1 : 0)] = 1;
    const BernsteinTriangle wdq = w * dq;
    for (std::size_t i = 0; i < h.coefficients().size(); ++i)
      h.coefficients()[i] += wdq.coefficients()[i];
  }
  double hscale = 0;
  for (double x : h.coefficients())
    hscale = std::max(hscale, std::abs(x));
  const double margin = 1e3 * 64 * std::numeric_limits<double>::epsilon() * hscale;
  for (double x : h.coefficients())
    if (!(side * x > margin))
      return std::nullopt;
  return CriticalEdge{c, side, slack};
}

} // namespace hoct
