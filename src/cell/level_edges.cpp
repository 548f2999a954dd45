#include "cell/level_edges.hpp"

#include "poly/reference_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hoct {
namespace {

constexpr int kMaxSplits = 8; // halvings of the edge where the coefficients' signs are mixed

// +1 / -1 if the polynomial with Bernstein coefficients c is above `margin` / below -margin on
// all of [0, 1] (certified on the coefficients, halving up to `depth` times), else 0.
int strict_sign(const std::vector<double> &c, double margin, int depth) {
  const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
  if (*lo > margin)
    return 1;
  if (*hi < -margin)
    return -1;
  // A subdivision can only help when the ends already have the sign.
  if (depth == 0 ||
      !(std::min(c.front(), c.back()) > margin || std::max(c.front(), c.back()) < -margin))
    return 0;
  const std::size_t n = c.size() - 1;
  std::vector<double> w = c, left(n + 1), right(n + 1);
  left[0] = w[0];
  right[n] = w[n];
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t i = 0; i + r <= n; ++i)
      w[i] = 0.5 * (w[i] + w[i + 1]);
    left[r] = w[0];
    right[n - r] = w[n - r];
  }
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
  return strict_sign(g.along(inward_normal(k)).edge(k).coefficients(), margin, kMaxSplits) != 0;
}

} // namespace hoct
