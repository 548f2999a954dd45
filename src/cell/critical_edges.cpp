#include "cell/critical_edges.hpp"

#include "cell/level_edges.hpp"
#include "poly/lattice.hpp"
#include "poly/reference_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {
namespace {

// The row of lattice point (a, b) of degree d counted from local edge k (0: on the edge): the
// index of the barycentric coordinate that vanishes there.
int row(int d, int k, int a, int b) { return k == 0 ? b : (k == 1 ? d - a - b : a); }

// Lattice point (a, b) of degree d moved two rows towards edge k, in degree d - 2.
int q_index(int d, int k, int a, int b) {
  return k == 0 ? lattice_index(d - 2, a, b - 2)
                : (k == 1 ? lattice_index(d - 2, a, b) : lattice_index(d - 2, a - 2, b));
}

double max_abs(const BernsteinTriangle &p) {
  double m = 0;
  for (double x : p.coefficients())
    m = std::max(m, std::abs(x));
  return m;
}

// The whole edge critical: g = c + w^2 q with q of one sign and D / w of that sign.
std::optional<CriticalEdge> whole_edge(const BernsteinTriangle &g, int k, double c,
                                       double precision) {
  const int d = g.degree();
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
  const int side = lo > near ? 1 : (hi < -near ? -1 : 0);
  if (side == 0)
    return std::nullopt;
  // D / w = 2 q |grad w|^2 + w (grad q . grad w), of degree d - 2.
  const Vec2 gw = inward_normal(k); // grad w in reference coordinates
  BernsteinTriangle h = q;
  for (double &x : h.coefficients())
    x *= 2 * (gw[0] * gw[0] + gw[1] * gw[1]);
  if (d >= 3) {
    // w in degree 1: v (k = 0), 1 - u - v (k = 1: the corner (0, 0)), u (k = 2).
    BernsteinTriangle w(1);
    w.coefficients()[lattice_index(1, k == 2 ? 1 : 0, k == 0 ? 1 : 0)] = 1;
    const BernsteinTriangle wdq = w * q.along(gw);
    for (std::size_t i = 0; i < h.coefficients().size(); ++i)
      h.coefficients()[i] += wdq.coefficients()[i];
  }
  const double margin = 1e3 * 64 * std::numeric_limits<double>::epsilon() * max_abs(h);
  for (double x : h.coefficients())
    if (!(side * x > margin))
      return std::nullopt;
  return CriticalEdge{c, side, true, 3u, slack};
}

} // namespace

std::optional<CriticalEdge> critical_edge(const BernsteinTriangle &g, int k, double precision) {
  const int d = g.degree();
  if (d < 1)
    return std::nullopt;
  // The value at the edge's first corner (corner k).
  const double c =
      k == 0 ? g.coefficient(0, 0) : (k == 1 ? g.coefficient(d, 0) : g.coefficient(0, d));
  const BernsteinTriangle dw = g.along(inward_normal(k)); // D: inward_normal(k) is grad w
  const double margin = edge_derivative_margin(g, precision);
  // D on the edge: all of it within the margin of zero is a whole critical edge.
  const int m = d - 1;
  bool flat = true;
  for (int t = 0; t <= m; ++t)
    flat = flat && std::abs(dw.coefficients()[edge_lattice_index(m, k, t)]) <= margin;
  if (flat)
    return d >= 2 ? whole_edge(g, k, c, precision) : std::nullopt;
  // Critical ends: D of one strict sign but at the edge's corners, which may vanish.
  const int first = edge_lattice_index(m, k, 0), second = edge_lattice_index(m, k, m);
  int side = 0;
  for (double x : dw.coefficients())
    if (std::abs(x) > margin) {
      side = x > 0 ? 1 : -1;
      break;
    }
  if (side == 0)
    return std::nullopt;
  unsigned ends = 0;
  double slack = 0;
  for (int i = 0; i < static_cast<int>(dw.coefficients().size()); ++i) {
    const double x = dw.coefficients()[static_cast<std::size_t>(i)];
    if (side * x > margin)
      continue;
    if ((i == first || i == second) && std::abs(x) <= margin) {
      ends |= i == first ? 1u : 2u;
      slack = std::max(slack, std::abs(x));
      continue;
    }
    return std::nullopt;
  }
  if (ends == 0)
    return std::nullopt; // a level edge (cell/level_edges.hpp), not this
  return CriticalEdge{c, side, false, ends, slack};
}

} // namespace hoct
