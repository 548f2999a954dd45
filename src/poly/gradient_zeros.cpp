#include "poly/gradient_zeros.hpp"

#include "poly/monomial.hpp"
#include "poly/tensor_bernstein.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {
namespace {

struct Iv {
  double lo, hi;
};
Iv operator+(Iv a, Iv b) { return {a.lo + b.lo, a.hi + b.hi}; }
Iv operator*(double s, Iv a) { return s >= 0 ? Iv{s * a.lo, s * a.hi} : Iv{s * a.hi, s * a.lo}; }
Iv operator*(Iv a, Iv b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}

struct Box {
  double u0, v0, w;
  TensorBernstein p, q; // g_u and g_v on the box
};

} // namespace

GradientZeros find_gradient_zeros(const BernsteinTriangle &g, const GradientZeroOptions &opt) {
  GradientZeros out;
  const int d = g.degree();
  if (d <= 0 || g.is_constant()) {
    out.constant = true;
    return out;
  }
  if (d == 1)
    return out; // a non-constant linear field has no critical point
  const BernsteinTriangle gu = g.du(), gv = g.dv();
  double scale = 0;
  for (const auto *c : {&gu.coefficients(), &gv.coefficients()})
    for (double x : *c)
      scale = std::max(scale, std::abs(x));
  // Constant up to rounding: the gradient is round-off of the values (e.g. a constant field
  // converted from Lagrange to Bernstein form).
  double value_scale = 0;
  for (double x : g.coefficients())
    value_scale = std::max(value_scale, std::abs(x));
  if (scale <= opt.constant_tolerance * value_scale) {
    out.constant = true;
    return out;
  }
  // Most cells of a smooth field: one gradient component keeps its sign on the whole closed
  // triangle (its Bernstein coefficients share a sign), so there is no critical point at all.
  {
    const auto [ulo, uhi] = gu.bounds();
    const auto [vlo, vhi] = gv.bounds();
    if (ulo > 0 || uhi < 0 || vlo > 0 || vhi < 0)
      return out;
  }
  const BernsteinTriangle guu = gu.du(), guv = gu.dv(), gvv = gv.dv();
  const std::vector<double> muu = to_monomial(guu), muv = to_monomial(guv), mvv = to_monomial(gvv);
  const double eps = std::numeric_limits<double>::epsilon();
  const double f_err = 64 * eps * scale; // bound on the rounding of a gradient evaluation

  // Newton's method from (u, v); gives up when the iterate leaves the square of half-width
  // `reach` around (cu, cv) (it is then heading for another zero or diverging).
  auto newton = [&](double &u, double &v, double cu = 0.5, double cv = 0.5, double reach = 10) {
    for (int it = 0; it < 40; ++it) {
      const double fu = gu(u, v), fv = gv(u, v);
      const double a = guu(u, v), b = guv(u, v), c = gvv(u, v);
      const double det = a * c - b * b;
      if (!(std::abs(det) > 0))
        return false;
      const double du = (c * fu - b * fv) / det, dv = (a * fv - b * fu) / det;
      u -= du;
      v -= dv;
      if (!std::isfinite(u) || !std::isfinite(v) || std::abs(u - cu) > reach ||
          std::abs(v - cv) > reach)
        return false;
      if (std::abs(du) + std::abs(dv) <= 4 * eps * (1 + std::abs(u) + std::abs(v)))
        return true;
    }
    return true;
  };

  // Krawczyk on the box centred at (cx, cy) with half-widths (rx, ry), around the point (x, y)
  // inside it: 1 = a unique zero in the box, -1 = no zero in the box, 0 = undecided.
  auto krawczyk = [&](double cx, double cy, double rx, double ry, double x, double y) {
    const double a = guu(x, y), b = guv(x, y), c = gvv(x, y);
    const double det = a * c - b * b;
    if (!(std::abs(det) > 0) || !std::isfinite(det))
      return 0;
    const double y00 = c / det, y01 = -b / det, y10 = -b / det, y11 = a / det;
    const auto [uu_lo, uu_hi] = monomial_range(muu, guu.degree(), cx, cy, rx, ry);
    const auto [uv_lo, uv_hi] = monomial_range(muv, guv.degree(), cx, cy, rx, ry);
    const auto [vv_lo, vv_hi] = monomial_range(mvv, gvv.degree(), cx, cy, rx, ry);
    const Iv J00{uu_lo, uu_hi}, J01{uv_lo, uv_hi}, J10{uv_lo, uv_hi}, J11{vv_lo, vv_hi};
    // M = I - Y J(X)
    const Iv M00 = Iv{1, 1} + (-1.0) * (y00 * J00 + y01 * J10);
    const Iv M01 = (-1.0) * (y00 * J01 + y01 * J11);
    const Iv M10 = (-1.0) * (y10 * J00 + y11 * J10);
    const Iv M11 = Iv{1, 1} + (-1.0) * (y10 * J01 + y11 * J11);
    const double fu = gu(x, y), fv = gv(x, y);
    const Iv F0{fu - f_err, fu + f_err}, F1{fv - f_err, fv + f_err};
    const Iv D0{cx - rx - x, cx + rx - x}, D1{cy - ry - y, cy + ry - y};
    const Iv K0 = Iv{x, x} + (-1.0) * (y00 * F0 + y01 * F1) + M00 * D0 + M01 * D1;
    const Iv K1 = Iv{y, y} + (-1.0) * (y10 * F0 + y11 * F1) + M10 * D0 + M11 * D1;
    const double slack = 8 * eps * (1 + std::abs(x) + std::abs(y));
    if (K0.hi + slack < cx - rx || K0.lo - slack > cx + rx || K1.hi + slack < cy - ry ||
        K1.lo - slack > cy + ry)
      return -1;
    if (K0.lo - slack > cx - rx && K0.hi + slack < cx + rx && K1.lo - slack > cy - ry &&
        K1.hi + slack < cy + ry)
      return 1;
    return 0;
  };

  struct Found {
    double u, v, cx, cy, rx, ry;
    bool certified;
  };
  std::vector<Found> found;
  auto known = [&](double u, double v) {
    for (const Found &f : found)
      if (f.certified && std::abs(u - f.cx) <= f.rx && std::abs(v - f.cy) <= f.ry)
        return true;
    return false;
  };

  std::vector<Box> stack;
  stack.push_back(
      {0.0, 0.0, 1.0, TensorBernstein::from_triangle(gu), TensorBernstein::from_triangle(gv)});
  const double tol = opt.boundary_tolerance;
  int64_t deep = 0;
  while (!stack.empty()) {
    Box b = std::move(stack.back());
    stack.pop_back();
    if (++out.boxes > opt.max_boxes) {
      out.budget_exhausted = true;
      break;
    }
    if (b.u0 + b.v0 > 1 + tol)
      continue; // entirely outside the triangle
    if (b.p.excludes_zero() || b.q.excludes_zero())
      continue;
    const double h = 0.5 * b.w;
    const double cx = b.u0 + h, cy = b.v0 + h;
    // Inside a box where Krawczyk already proved a unique zero (found and recorded): nothing
    // else to find here.
    bool covered = false;
    for (const Found &f : found)
      covered = covered || (f.certified && b.u0 >= f.cx - f.rx && b.u0 + b.w <= f.cx + f.rx &&
                            b.v0 >= f.cy - f.ry && b.v0 + b.w <= f.cy + f.ry);
    if (covered)
      continue;
    if (b.w <= 0.25) {
      // Certify on the box inflated by a quarter, so zeros on box edges are interior.
      const double r = 1.25 * h;
      double x = cx, y = cy;
      if (!newton(x, y, cx, cy, 2 * r) || std::abs(x - cx) > r || std::abs(y - cy) > r) {
        x = cx;
        y = cy;
      }
      const int k = krawczyk(cx, cy, r, r, x, y);
      if (k == -1)
        continue;
      if (k == 1) {
        newton(x, y); // converges inside the box (Krawczyk)
        if (!known(x, y))
          found.push_back({x, y, cx, cy, r, r, true});
        continue;
      }
    }
    if (b.w <= opt.deep_width && ++deep > opt.deep_limit) {
      out.budget_exhausted = true;
      break;
    }
    if (b.w <= opt.resolution) {
      found.push_back({cx, cy, cx, cy, h, h, false});
      continue;
    }
    const auto qp = b.p.quarters(), qq = b.q.quarters();
    for (int k = 3; k >= 0; --k)
      stack.push_back({b.u0 + (k & 1) * h, b.v0 + (k >> 1) * h, h, qp[k], qq[k]});
  }

  // Keep zeros in the closed triangle (within tolerance); merge unresolved neighbours.
  std::sort(found.begin(), found.end(),
            [](const Found &a, const Found &b) { return a.u < b.u || (a.u == b.u && a.v < b.v); });
  for (const Found &f : found) {
    if (f.u < -tol || f.v < -tol || f.u + f.v > 1 + tol)
      continue;
    if (!f.certified) {
      bool merged = false;
      for (auto &z : out.zeros)
        if (!z.certified && std::abs(z.u - f.u) <= z.radius + 2 * f.rx &&
            std::abs(z.v - f.v) <= z.radius + 2 * f.ry) {
          merged = true;
          break;
        }
      if (merged)
        continue;
      ++out.unresolved;
    }
    GradientZero z;
    z.u = f.u;
    z.v = f.v;
    z.certified = f.certified;
    z.radius = f.rx;
    z.near_boundary = f.u <= tol || f.v <= tol || f.u + f.v >= 1 - tol;
    out.zeros.push_back(z);
  }
  return out;
}

} // namespace hoct
