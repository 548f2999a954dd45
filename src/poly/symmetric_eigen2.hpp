// The eigen-decomposition of a symmetric 2 x 2 matrix (a Hessian), in closed form: the
// eigenvalues mean -+ r, and unit eigenvectors at the angle theta with tan(2 theta) =
// 2 b / (a - d). One formula for every caller, so that the sectors, the critical-curve cover and
// the degenerate-point searches agree on the directions they use.
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <cmath>

namespace hoct {

struct SymmetricEigen2 {
  double lo, hi;   // eigenvalues, lo <= hi
  Vec2 v_lo, v_hi; // their unit eigenvectors
  // The eigenvalue of larger / smaller magnitude (ties: hi is the larger).
  double larger() const { return std::abs(hi) >= std::abs(lo) ? hi : lo; }
  double smaller() const { return std::abs(hi) >= std::abs(lo) ? lo : hi; }
};

// h's off-diagonal entry is taken as the mean of h[0][1] and h[1][0] (equal for a Hessian).
inline SymmetricEigen2 symmetric_eigen2(const Mat2 &h) {
  const double a = h[0][0], b = 0.5 * (h[0][1] + h[1][0]), d = h[1][1];
  const double mean = 0.5 * (a + d), r = std::hypot(0.5 * (a - d), b);
  const double theta = 0.5 * std::atan2(2 * b, a - d);
  return {
      mean - r, mean + r, {-std::sin(theta), std::cos(theta)}, {std::cos(theta), std::sin(theta)}};
}

} // namespace hoct
