// All zeros of the gradient of a triangle polynomial g in the closed reference triangle: the
// interior critical points of a cell (at most (d-1)^2 isolated ones). Boxes covering the triangle
// are subdivided, pruned where a gradient component's Bernstein coefficients share a sign, and
// each zero is certified unique in its box by the Krawczyk test (interval Newton with the
// Hessian's Bernstein enclosure), which also proves the Hessian non-singular there. What cannot be
// certified down to the resolution is reported, never dropped: unresolved clusters (degenerate
// zeros) and a critical-curve flag when the box budget runs out.
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace hoct {

struct GradientZero {
  double u = 0, v = 0;
  bool certified = false;     // unique and non-degenerate (Krawczyk)
  bool near_boundary = false; // within boundary_tolerance of the triangle's boundary
  double radius = 0;          // half-width of the box it was found in
};

struct GradientZeroOptions {
  double resolution = 1e-9; // boxes below this width are reported unresolved
  // Boxes narrower than deep_width still undecided: more than deep_limit of them means the
  // zeros form a curve (or a region), not isolated points.
  double deep_width = 1e-6;
  int64_t deep_limit = 64;
  double boundary_tolerance = 1e-9;  // "on or near the boundary"
  int64_t max_boxes = 50000;         // budget: exhausted means a curve of critical points
  double constant_tolerance = 1e-12; // |gradient coefficients| <= this * |values|: constant
  // The cell's shape, asked for only when the search in the reference triangle leaves zeros
  // unresolved: a 2x2 matrix T with |T (du, dv)| the length of a reference step (du, dv) in the
  // cell (e.g. the R factor of the geometry's Jacobian). When T's condition number exceeds
  // frame_anisotropy (a sliver), the search runs again in the coordinates T (u, v), where the
  // cell has its own shape, and its result is kept if it resolves every zero: for a field that
  // is smooth in the plane, the gradient components of a sliver are nearly parallel in the
  // reference triangle and its Hessian nearly singular, so that squares never certify.
  std::function<Mat2()> frame;
  double frame_anisotropy = 16;
  // Squares of the reference triangle (centre u, v and half-width) the caller accounts for
  // itself (degenerate critical points: cell/degenerate_points.hpp): boxes inside one are not
  // searched, so whatever zeros they hold are neither reported nor counted.
  std::vector<std::array<double, 3>> excluded;
};

struct GradientZeros {
  std::vector<GradientZero> zeros;
  bool constant = false;         // the gradient vanishes identically
  bool budget_exhausted = false; // likely a curve of critical points (degenerate cell)
  int64_t boxes = 0;             // boxes examined
  int64_t unresolved = 0;        // zeros reported uncertified
  bool framed = false;           // found by the search in the cell's own shape
  // Where the search stopped at the limit of deep boxes (budget_exhausted): the centre of the
  // last one, next to a curve of critical points or a degenerate zero.
  std::optional<Vec2> stopped_at;
};

// The cheap first look of find_gradient_zeros at a polynomial's coefficients (canonical lattice
// order): constant (up to rounding), certainly without a gradient zero (a gradient component's
// Bernstein coefficients share a sign, or the field is linear), or to be searched. Lets callers
// skip building the polynomial for most cells of a smooth field.
struct GradientScreen {
  enum Verdict { kSearch, kNoZero, kConstant } verdict = kSearch;
  double scale = 0; // largest |gradient coefficient|
};
GradientScreen screen_gradient(std::span<const double> coefficients, int degree,
                               double constant_tolerance);

GradientZeros find_gradient_zeros(const BernsteinTriangle &g,
                                  const GradientZeroOptions &options = {});
// The same with g's screen already computed (screen_gradient of g's coefficients with
// options.constant_tolerance), as the cell loop has it.
GradientZeros find_gradient_zeros(const BernsteinTriangle &g, const GradientZeroOptions &options,
                                  const GradientScreen &screen);

} // namespace hoct
