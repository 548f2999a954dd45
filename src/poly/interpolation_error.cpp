#include "poly/interpolation_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {

double enclosing_radius_squared(const Vec2 &a, const Vec2 &b, const Vec2 &c) {
  auto d2 = [](const Vec2 &p, const Vec2 &q) {
    return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
  };
  const double ab = d2(a, b), bc = d2(b, c), ca = d2(c, a);
  const double longest = std::max({ab, bc, ca});
  // Right or obtuse: the longest side is a diameter of the smallest disk.
  if (2 * longest >= ab + bc + ca)
    return longest / 4;
  // Acute: the circumcircle, R^2 = |ab|^2 |bc|^2 |ca|^2 / (16 area^2).
  const double cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  const double area2 = cross * cross / 4;
  return area2 > 0 ? ab * bc * ca / (16 * area2) : longest / 4;
}

InterpolationError::InterpolationError(const BernsteinTriangle &p) {
  const int d = p.degree();
  double coefficients = 0;
  for (double x : p.coefficients())
    coefficients = std::max(coefficients, std::abs(x));
  // The stand-in's corner values are p evaluated by de Casteljau: a few units in the last place
  // of the coefficients' magnitude each.
  rounding_ = 4 * (d + 1) * std::numeric_limits<double>::epsilon() * coefficients;
  if (d < 2)
    return;
  // Largest coefficient magnitudes of p_uu, p_uv, p_vv (degree d - 2).
  double uu = 0, uv = 0, vv = 0;
  for (int b = 0; b <= d - 2; ++b)
    for (int a = 0; a + b <= d - 2; ++a) {
      uu = std::max(uu, std::abs(p.coefficient(a + 2, b) - 2 * p.coefficient(a + 1, b) +
                                 p.coefficient(a, b)));
      uv = std::max(uv, std::abs(p.coefficient(a + 1, b + 1) - p.coefficient(a + 1, b) -
                                 p.coefficient(a, b + 1) + p.coefficient(a, b)));
      vv = std::max(vv, std::abs(p.coefficient(a, b + 2) - 2 * p.coefficient(a, b + 1) +
                                 p.coefficient(a, b)));
    }
  const double k = static_cast<double>(d) * (d - 1);
  uu *= k;
  uv *= k;
  vv *= k;
  // The spectral norm of [[uu, uv], [uv, vv]] entrywise bounded: Gershgorin and Frobenius, the
  // smaller; a little more for the rounding of these differences.
  const double norm =
      std::min(std::max(uu + uv, uv + vv), std::sqrt(uu * uu + 2 * uv * uv + vv * vv));
  hessian_ = norm * (1 + 16 * std::numeric_limits<double>::epsilon()) +
             16 * k * std::numeric_limits<double>::epsilon() * coefficients;
}

double InterpolationError::on(const Vec2 &a, const Vec2 &b, const Vec2 &c) const {
  return hessian_ * enclosing_radius_squared(a, b, c) / 2 + rounding_;
}

} // namespace hoct
