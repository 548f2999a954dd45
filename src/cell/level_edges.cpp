#include "cell/level_edges.hpp"

#include "poly/reference_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hoct {
namespace {

constexpr int kMaxSplits = 8; // halvings of the edge where the coefficients' signs are mixed

// +1 / -1 if p is above `margin` / below -margin on all of [0, 1] (certified on its Bernstein
// coefficients, halving up to `depth` times), else 0.
int strict_sign(const BernsteinPoly &p, double margin, int depth) {
  const auto [lo, hi] = p.bounds();
  if (lo > margin)
    return 1;
  if (hi < -margin)
    return -1;
  // A subdivision can only help when the ends already have the sign.
  const std::vector<double> &c = p.coefficients();
  if (depth == 0 ||
      !(std::min(c.front(), c.back()) > margin || std::max(c.front(), c.back()) < -margin))
    return 0;
  const auto [left, right] = p.split(0.5);
  const int a = strict_sign(left, margin, depth - 1);
  return a != 0 && a == strict_sign(right, margin, depth - 1) ? a : 0;
}

} // namespace

double edge_derivative_margin(const BernsteinTriangle &g, double precision) {
  return std::max(1e3 * 64 * std::numeric_limits<double>::epsilon() * g.gradient_scale(),
                  2 * g.degree() * precision);
}

bool is_level_edge(const BernsteinTriangle &g, int k, double precision) {
  const int d = g.degree();
  if (d < 1)
    return false;
  const double margin = edge_derivative_margin(g, precision);
  return strict_sign(g.along(inward_normal(k)).edge(k), margin, kMaxSplits) != 0;
}

} // namespace hoct
