#include "poly/interpolation_error.hpp"

#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>

namespace hoct {
namespace {

double conversion_norm(int degree) {
  static std::array<std::once_flag, kMaxDegree + 1> once;
  static std::array<double, kMaxDegree + 1> norm{};
  std::call_once(once[degree], [&] { norm[degree] = lagrange_to_bernstein_norm(degree); });
  return norm[degree];
}

} // namespace

InterpolationError::InterpolationError(const BernsteinTriangle &p) : p_(p) {
  const int d = p.degree();
  if (d <= 1)
    return;
  conversion_ = &lagrange_to_bernstein_triangle(d);
  double coefficients = 0;
  for (double x : p.coefficients())
    coefficients = std::max(coefficients, std::abs(x));
  // The samples (de Casteljau: a few units in the last place of the coefficients' magnitude
  // each), amplified by the conversion.
  rounding_ = 4 * d * conversion_norm(d) * coefficients;
  samples_.resize(static_cast<std::size_t>(lattice_size(d)));
  linear_.resize(samples_.size());
}

double InterpolationError::on(const Vec2 &a, const Vec2 &b, const Vec2 &c) {
  const int d = p_.degree();
  if (d <= 1)
    return 0; // p is its own interpolant
  const int n = lattice_size(d);
  // p at the sub-triangle's degree-d lattice: node i at barycentrics (1 - s - t, s, t) of
  // (a, b, c), as the conversion tables order them; the corners are nodes too.
  double magnitude = 0;
  for (int i = 0; i < n; ++i) {
    const auto q = lattice_point(d, i);
    const double s = static_cast<double>(q[0]) / d, t = static_cast<double>(q[1]) / d;
    const double r = 1 - s - t;
    samples_[i] = p_(r * a[0] + s * b[0] + t * c[0], r * a[1] + s * b[1] + t * c[1]);
    magnitude = std::max(magnitude, std::abs(samples_[i]));
  }
  const double pa = samples_[corner_index(d, 0)], pb = samples_[corner_index(d, 1)],
               pc = samples_[corner_index(d, 2)];
  const std::vector<double> &m = *conversion_;
  double error = 0;
  for (int i = 0; i < n; ++i) {
    const auto q = lattice_point(d, i);
    const double s = static_cast<double>(q[0]) / d, t = static_cast<double>(q[1]) / d;
    double coefficient = 0;
    for (int j = 0; j < n; ++j)
      coefficient += m[static_cast<std::size_t>(i) * n + j] * samples_[j];
    error = std::max(error, std::abs(coefficient - ((1 - s - t) * pa + s * pb + t * pc)));
  }
  // Plus the rounding of the samples and of the sums.
  return error + (rounding_ + 4 * n * magnitude) * std::numeric_limits<double>::epsilon();
}

} // namespace hoct
