#include "poly/gradient_zeros.hpp"

#include "poly/degree_dispatch.hpp"
#include "poly/lattice.hpp"
#include "poly/monomial.hpp"
#include "poly/tensor_bernstein.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

// A box of the subdivision; its coefficients (g_u then g_v, tensor Bernstein form on the box)
// sit at `offset` in the arena, which is used as a stack like the boxes themselves.
struct Box {
  double u0, v0, w, wy; // corner, widths along u and v (equal unless the search is framed)
  std::size_t offset;
};

// A polynomial in monomial form a[i * (d+1) + j] u^i v^j (a view of scratch storage),
// evaluated by nested Horner (evaluate below) with a rigorous bound on the rounding error.
struct Monomial {
  double *a = nullptr;
  int d = 0;
  std::size_t size() const { return static_cast<std::size_t>(d + 1) * (d + 1); }
  // Bound on |computed - exact| of its Horner value at (u, v), from r, the Horner sum of the
  // absolute values at (|u|, |v|): gamma_{4d+4} times r (Higham, Accuracy and Stability, 5.1),
  // with margin.
  double error_bound_of(double r) const {
    return 2 * (4 * d + 6) * std::numeric_limits<double>::epsilon() * r;
  }
};

// Nested Horner of K polynomials of one degree at one point, sum a[k][i * (d+1) + j] u^i v^j
// (or, Abs, of the absolute values), degree D (or d at run time when D < 0); the K chains
// interleaved so that their latencies overlap, each the same operations as on its own.
template <int D, bool Abs, int K>
void horner_k(const double *const a[K], int d_run, double u, double v, double out[K]) {
  const int d = D >= 0 ? D : d_run;
  double r[K] = {};
  for (int i = d; i >= 0; --i) {
    const std::size_t row = static_cast<std::size_t>(i) * (d + 1);
    double s[K] = {};
    for (int j = d - i; j >= 0; --j)
      for (int k = 0; k < K; ++k)
        s[k] = s[k] * v + (Abs ? std::abs(a[k][row + j]) : a[k][row + j]);
    for (int k = 0; k < K; ++k)
      r[k] = r[k] * u + s[k];
  }
  for (int k = 0; k < K; ++k)
    out[k] = r[k];
}

// The values (Abs = false) or the sums behind error_bound_of (Abs = true, at (|u|, |v|)) of K
// polynomials of one degree at (u, v) at once.
template <bool Abs, int K>
void evaluate(const Monomial *const p[K], double u, double v, double out[K]) {
  const double *a[K];
  for (int k = 0; k < K; ++k)
    a[k] = p[k]->a;
  const int d = p[0]->d;
  dispatch_degree(d, [&](auto D) {
    horner_k<D.value, Abs, K>(a, d, Abs ? std::abs(u) : u, Abs ? std::abs(v) : v, out);
  });
}

// The partial derivative of p in u (or v), of degree max(d - 1, 0), into storage at `out`.
Monomial derivative(const Monomial &p, bool in_u, double *out) {
  Monomial m{out, std::max(p.d - 1, 0)};
  std::fill(out, out + m.size(), 0.0);
  for (int i = 0; i <= p.d; ++i)
    for (int j = 0; i + j <= p.d; ++j) {
      const double c = p.a[static_cast<std::size_t>(i) * (p.d + 1) + j];
      if (in_u && i > 0)
        m.a[static_cast<std::size_t>(i - 1) * (m.d + 1) + j] += i * c;
      if (!in_u && j > 0)
        m.a[static_cast<std::size_t>(i) * (m.d + 1) + (j - 1)] += j * c;
    }
  return m;
}

// A polynomial's Taylor expansion at a box centre (taylor_expansion), for enclosures of it and
// of combinations with others over boxes around that centre.
struct Taylor {
  const double *e = nullptr;
  int d = 0;
  double magnitude = 0; // 64 eps times it bounds the rounding of every coefficient
};
Taylor expand(const Monomial &p, double x, double y, double *storage) {
  return {storage, p.d, taylor_expansion(p.a, p.d, x, y, storage)};
}

// Enclosure of s P + t Q over the box |u - x| <= rx, |v - y| <= ry, for P and Q (same degree)
// expanded at (x, y): the centre coefficient plus or minus the others times the radii' powers,
// widened by the rounding of the expansions (64 eps of their magnitudes), of the combination
// and of the sum (4 eps of its terms). Beyond degree 31 (binomials no longer exact in the
// expansion) the whole line.
template <int D>
Iv combination_range_fixed(double s, const Taylor &P, double t, const Taylor &Q, double rx,
                           double ry) {
  const int d = D >= 0 ? D : P.d;
  const double eps = std::numeric_limits<double>::epsilon();
  double centre = 0, spread = 0, terms = 0, pa = 1;
  for (int a = 0; a <= d; ++a, pa *= rx) {
    double w = pa;
    for (int b = 0; a + b <= d; ++b, w *= ry) {
      const std::size_t k = static_cast<std::size_t>(a) * (d + 1) + b;
      const double x = s * P.e[k], y = t * Q.e[k];
      terms += (std::abs(x) + std::abs(y)) * w;
      if (a == 0 && b == 0)
        centre = x + y;
      else
        spread += std::abs(x + y) * w;
    }
  }
  const double round =
      64 * eps * (std::abs(s) * P.magnitude + std::abs(t) * Q.magnitude) + 4 * eps * terms;
  return {centre - spread - round, centre + spread + round};
}
Iv combination_range(double s, const Taylor &P, double t, const Taylor &Q, double rx, double ry) {
  if (P.d >= 32)
    return {-INFINITY, INFINITY};
  return dispatch_degree(
      P.d, [&](auto D) { return combination_range_fixed<D.value>(s, P, t, Q, rx, ry); });
}

// True if every coefficient exceeds `margin` in absolute value with one common sign: the
// polynomial has no zero on the box. (Stops at the first coefficient against the sign of the
// first: most boxes that survive fail early.)
bool excludes_zero(const double *c, std::size_t n, double margin) {
  if (c[0] > margin) {
    for (std::size_t i = 1; i < n; ++i)
      if (!(c[i] > margin))
        return false;
    return true;
  }
  if (c[0] < -margin) {
    for (std::size_t i = 1; i < n; ++i)
      if (!(c[i] < -margin))
        return false;
    return true;
  }
  return false;
}

// No common zero of p and q on the box if a p + b q has one sign there, with (a, b) the
// gradient at the box's centre (where a p + b q = |grad|^2 > 0). Rounding of the combination
// and of the coefficients (margins mp, mq) is accounted for.
bool combination_excludes_zero(const double *p, const double *q, std::size_t n, double a, double b,
                               double mp, double mq) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double base = std::abs(a) * mp + std::abs(b) * mq;
  // +1: every term above its margin, -1: every term below minus its margin, 0: neither. The
  // first term decides which sign the others must have; the loop stops at the first that has not.
  auto side = [&](std::size_t i) {
    const double x = a * p[i], y = b * q[i], h = x + y;
    const double margin = base + 2 * eps * (std::abs(x) + std::abs(y));
    return h > margin ? 1 : h < -margin ? -1 : 0;
  };
  const int s = n > 0 ? side(0) : 0;
  if (s == 0)
    return false;
  for (std::size_t i = 1; i < n; ++i)
    if (side(i) != s)
      return false;
  return true;
}

GradientZeros search_zeros(const BernsteinTriangle &g, const GradientZeroOptions &opt, double scale,
                           bool use_frame);

} // namespace

namespace {

// Extremes of the coefficient differences c[a+1,b] - c[a,b] (lo[0], hi[0]) and
// c[a,b+1] - c[a,b] (lo[1], hi[1]) over the lattice of degree D (d at run time if D < 0).
template <int D> void difference_range(const double *c, int d_run, double lo[2], double hi[2]) {
  const int d = D >= 0 ? D : d_run;
  double ulo = INFINITY, uhi = -INFINITY, vlo = INFINITY, vhi = -INFINITY;
#pragma GCC unroll 16
  for (int b = 0; b < d; ++b) {
    const double *row = &c[lattice_index(d, 0, b)], *up = &c[lattice_index(d, 0, b + 1)];
#pragma GCC unroll 16
    for (int a = 0; a + b < d; ++a) {
      const double x = row[a + 1] - row[a], y = up[a] - row[a];
      ulo = std::min(ulo, x);
      uhi = std::max(uhi, x);
      vlo = std::min(vlo, y);
      vhi = std::max(vhi, y);
    }
  }
  lo[0] = ulo;
  hi[0] = uhi;
  lo[1] = vlo;
  hi[1] = vhi;
}

} // namespace

GradientScreen screen_gradient(std::span<const double> coefficients, int d,
                               double constant_tolerance) {
  GradientScreen r;
  if (d <= 0) {
    r.verdict = GradientScreen::kConstant;
    return r;
  }
  if (d == 1) {
    // A non-constant linear field has no critical point.
    r.verdict = std::all_of(coefficients.begin(), coefficients.end(),
                            [&](double x) { return x == coefficients[0]; })
                    ? GradientScreen::kConstant
                    : GradientScreen::kNoZero;
    return r;
  }
  // The gradient's Bernstein coefficients are d (c[a+1,b] - c[a,b]) and d (c[a,b+1] - c[a,b])
  // (as BernsteinTriangle::du and ::dv); first only their extremes (an unrolled pass for the
  // common degrees; scaling by d > 0 preserves the order and the signs exactly).
  double lo[2], hi[2];
  dispatch_degree(d, [&](auto D) { difference_range<D.value>(coefficients.data(), d, lo, hi); });
  const double ulo = d * lo[0], uhi = d * hi[0], vlo = d * lo[1], vhi = d * hi[1];
  r.scale = std::max({-ulo, uhi, -vlo, vhi});
  // Constant up to rounding: the gradient is round-off of the values (e.g. a constant field
  // converted from Lagrange to Bernstein form). Every value is within d differences of c[0,0],
  // so max |c| <= |c[0,0]| + scale (doubled for the differences' rounding): only a gradient
  // that small needs the values' largest magnitude.
  auto constant = [&] {
    if (r.scale > constant_tolerance * (std::abs(coefficients[0]) + 2 * r.scale))
      return false;
    double value_scale = 0;
    for (double x : coefficients)
      value_scale = std::max(value_scale, std::abs(x));
    return r.scale <= constant_tolerance * value_scale;
  };
  if (constant())
    r.verdict = GradientScreen::kConstant;
  // Most cells of a smooth field: one gradient component keeps its sign on the whole closed
  // triangle (its Bernstein coefficients share a sign), so there is no critical point at all.
  else if (ulo > 0 || uhi < 0 || vlo > 0 || vhi < 0)
    r.verdict = GradientScreen::kNoZero;
  // Else the same for the component along the mean gradient direction (a, b): if every
  // coefficient of a g_u + b g_v exceeds its rounding margin with one sign, so does the
  // polynomial on the closed triangle (a convex combination of them), and the gradient cannot
  // vanish there. Margins as in the box search (64 (m+1)^2 eps of the scale).
  else {
    const std::size_t n = static_cast<std::size_t>(lattice_size(d - 1));
    thread_local std::vector<double> grad;
    grad.resize(2 * n);
    double *gu = grad.data(), *gv = gu + n;
    {
      std::size_t k = 0;
      for (int b = 0; b < d; ++b) {
        const double *row = &coefficients[lattice_index(d, 0, b)];
        const double *up = &coefficients[lattice_index(d, 0, b + 1)];
        for (int a = 0; a + b < d; ++a, ++k) {
          gu[k] = d * (row[a + 1] - row[a]);
          gv[k] = d * (up[a] - row[a]);
        }
      }
    }
    const double eps = std::numeric_limits<double>::epsilon();
    auto excludes = [&](double a, double b) {
      const double margin = 64.0 * d * d * eps * r.scale * (std::abs(a) + std::abs(b));
      bool positive = true, negative = true;
      for (std::size_t k = 0; k < n && (positive || negative); ++k) {
        const double x = a * gu[k], y = b * gv[k];
        const double h = x + y, m = margin + 2 * eps * (std::abs(x) + std::abs(y));
        positive = positive && h > m;
        negative = negative && h < -m;
      }
      return positive || negative;
    };
    double a = 0, b = 0;
    {
      std::size_t k = 0;
      for (int j = 0; j < d; ++j) {
        const double *row = &coefficients[lattice_index(d, 0, j)];
        const double *up = &coefficients[lattice_index(d, 0, j + 1)];
        for (int i = 0; i + j < d; ++i, ++k) {
          a += row[i + 1] - row[i];
          b += up[i] - row[i];
        }
      }
    }
    // The mean gradient direction, then the rows of the inverse Hessian at the centroid (near a
    // zero they behave like u - u* and v - v*, as in the box search).
    bool none = excludes(a, b);
    if (!none && d >= 2) {
      const Mat2 h = BernsteinTriangle::jet_of(coefficients, d, 1.0 / 3, 1.0 / 3).hessian;
      none = excludes(h[1][1], -h[0][1]) || excludes(-h[0][1], h[0][0]);
    }
    if (none)
      r.verdict = GradientScreen::kNoZero;
  }
  return r;
}

GradientZeros find_gradient_zeros(const BernsteinTriangle &g, const GradientZeroOptions &opt) {
  return find_gradient_zeros(g, opt,
                             screen_gradient(g.coefficients(), g.degree(), opt.constant_tolerance));
}

GradientZeros find_gradient_zeros(const BernsteinTriangle &g, const GradientZeroOptions &opt,
                                  const GradientScreen &screen) {
  GradientZeros out;
  if (screen.verdict == GradientScreen::kConstant) {
    out.constant = true;
    return out;
  }
  if (screen.verdict == GradientScreen::kNoZero)
    return out;
  const double scale = screen.scale;
  // The search in the reference triangle; where it cannot resolve every zero and the cell is a
  // sliver, once more in the cell's own shape, whose result is kept if it resolves them all.
  // (Neither is preferred a priori: a field that is smooth in the plane is well-conditioned in
  // the shape of a sliver, a field that varies across the sliver as fast as along it, as in
  // boundary layers and in arbitrary node data, in the reference triangle.)
  out = search_zeros(g, opt, scale, false);
  if ((out.budget_exhausted || out.unresolved > 0) && opt.frame) {
    GradientZeros framed = search_zeros(g, opt, scale, true);
    if (framed.framed && !framed.budget_exhausted && framed.unresolved == 0) {
      framed.boxes += out.boxes;
      return framed;
    }
  }
  return out;
}

namespace {

GradientZeros search_zeros(const BernsteinTriangle &g, const GradientZeroOptions &opt, double scale,
                           bool use_frame) {
  GradientZeros out;
  const int d = g.degree();
  // The retry in the cell's shape gets a tenth of the budget: it is for slivers whose field is
  // smooth in the plane, where it needs a few boxes per cell, not for degenerate cells.
  const int64_t budget = use_frame ? std::max<int64_t>(opt.max_boxes / 10, 1) : opt.max_boxes;
  // Evaluation in monomial form (Horner) with rigorous rounding bounds; the subdivision itself
  // works on tensor Bernstein coefficients. The gradient components (Bernstein, then monomial),
  // the Hessian's entries and their Taylor expansions live in one per-thread buffer.
  const int m = d - 1;
  if (m > 60)
    throw std::invalid_argument("find_gradient_zeros: degree above 61 is not supported");
  const std::size_t tri = static_cast<std::size_t>(lattice_size(m)),
                    sz = static_cast<std::size_t>(m + 1) * (m + 1),
                    hsz = static_cast<std::size_t>(std::max(m, 1)) * std::max(m, 1);
  thread_local std::vector<double> store;
  store.resize(2 * tri + 2 * sz + 6 * hsz);
  double *bu = store.data(), *bv = bu + tri, *hessian_store = bv + tri + 2 * sz;
  for (int b = 0; b <= m; ++b)
    for (int a = 0; a <= m - b; ++a) {
      // As BernsteinTriangle::du and ::dv.
      const double c = g.coefficient(a, b);
      bu[lattice_index(m, a, b)] = d * (g.coefficient(a + 1, b) - c);
      bv[lattice_index(m, a, b)] = d * (g.coefficient(a, b + 1) - c);
    }
  Monomial mu{bv + tri, m}, mv{bv + tri + sz, m};
  to_monomial(bu, m, mu.a);
  to_monomial(bv, m, mv.a);
  const double eps = std::numeric_limits<double>::epsilon();
  // The coefficients themselves carry the rounding of their computation from the data (e.g. the
  // Lagrange -> Bernstein conversion), relative to the gradient's scale: a gradient component
  // below this level is noise, not a certified sign.
  const double f_err = 64 * eps * scale;
  // Noise levels of the two components searched (f_err unless the search is framed).
  double err_u = f_err, err_v = f_err;
  // The search domain: the unit square of box coordinates x, mapped to the reference triangle
  // by (u, v) = B x + c (the identity unless framed).
  Mat2 B{{{1, 0}, {0, 1}}};
  Vec2 c0{0, 0};
  bool framed = false;
  double root_w = 1, root_h = 1; // the search rectangle [0, root_w] x [0, root_h]
  if (use_frame) {
    const Mat2 T = opt.frame();
    const double det = T[0][0] * T[1][1] - T[0][1] * T[1][0];
    const double fro =
        T[0][0] * T[0][0] + T[0][1] * T[0][1] + T[1][0] * T[1][0] + T[1][1] * T[1][1];
    // Condition number from the Frobenius norm and the determinant (sigma1 sigma2 = |det|).
    const double ratio = std::abs(det) > 0 ? fro / std::abs(det) : INFINITY; // s1/s2 + s2/s1
    if (std::isfinite(ratio) && ratio > opt.frame_anisotropy + 1 / opt.frame_anisotropy) {
      framed = true;
      out.framed = true;
      // The cell in frame coordinates: corners 0, T e1, T e2; its bounding square becomes the
      // unit square of box coordinates.
      const double xs[3] = {0, T[0][0], T[0][1]}, ys[3] = {0, T[1][0], T[1][1]};
      const double xlo = *std::min_element(xs, xs + 3), ylo = *std::min_element(ys, ys + 3);
      const double lx = *std::max_element(xs, xs + 3) - xlo,
                   ly = *std::max_element(ys, ys + 3) - ylo, side = std::max(lx, ly);
      root_w = lx / side;
      root_h = ly / side;
      const Mat2 Ti{{{T[1][1] / det, -T[0][1] / det}, {-T[1][0] / det, T[0][0] / det}}};
      B = {{{side * Ti[0][0], side * Ti[0][1]}, {side * Ti[1][0], side * Ti[1][1]}}};
      c0 = {Ti[0][0] * xlo + Ti[0][1] * ylo, Ti[1][0] * xlo + Ti[1][1] * ylo};
      // The gradient in box coordinates: B^T (g_u, g_v) at B x + c.
      thread_local std::vector<double> pu, pv, au, av;
      for (auto *v : {&pu, &pv, &au, &av})
        v->resize(sz);
      compose_affine(mu.a, m, B, c0, pu.data(), au.data());
      compose_affine(mv.a, m, B, c0, pv.data(), av.data());
      // Bounds of |x^i y^j| where the search evaluates (the rectangle, boxes inflated by 1.25).
      double su = 0, sv = 0;
      for (int i = 0; i <= m; ++i)
        for (int j = 0; i + j <= m; ++j) {
          const std::size_t k = static_cast<std::size_t>(i) * (m + 1) + j;
          const double reach = std::pow(1.5 * root_w, i) * std::pow(1.5 * root_h, j);
          mu.a[k] = B[0][0] * pu[k] + B[1][0] * pv[k];
          mv.a[k] = B[0][1] * pu[k] + B[1][1] * pv[k];
          su += (std::abs(B[0][0]) * au[k] + std::abs(B[1][0]) * av[k]) * reach;
          sv += (std::abs(B[0][1]) * au[k] + std::abs(B[1][1]) * av[k]) * reach;
        }
      // The data's noise carried through B^T, and the rounding of the composition (every term
      // bounded by the composition of absolute values, at most (m + 2)^2 terms per coefficient).
      const double round = 4 * (m + 2) * (m + 2) * eps;
      err_u = (std::abs(B[0][0]) + std::abs(B[1][0])) * f_err + round * su;
      err_v = (std::abs(B[0][1]) + std::abs(B[1][1])) * f_err + round * sv;
    }
  }
  auto to_reference = [&](double x, double y) {
    return Vec2{B[0][0] * x + B[0][1] * y + c0[0], B[1][0] * x + B[1][1] * y + c0[1]};
  };
  const Monomial muu = derivative(mu, true, hessian_store),
                 muv = derivative(mu, false, hessian_store + hsz),
                 mvv = derivative(mv, false, hessian_store + 2 * hsz);
  double *taylor_store = hessian_store + 3 * hsz;
  const Monomial *const gradient[2] = {&mu, &mv};
  const Monomial *const hessian[3] = {&muu, &muv, &mvv};
  // The gradient (g[0], g[1]) and the Hessian's entries (h[0] = uu, h[1] = uv, h[2] = vv) at
  // a point, each by nested Horner.
  auto gradient_at = [&](double u, double v, double g[2]) {
    evaluate<false, 2>(gradient, u, v, g);
  };
  auto hessian_at = [&](double u, double v, double h[3]) { evaluate<false, 3>(hessian, u, v, h); };

  // Newton's method from (u, v); gives up when the iterate leaves the square of half-width
  // `reach` around (cu, cv) (it is then heading for another zero or diverging).
  // `last` receives the size |du| + |dv| of the last step taken. `start` may hold the gradient
  // and the Hessian at the starting point, already evaluated.
  struct Jet {
    double g[2], h[3];
  };
  auto newton = [&](double &u, double &v, double cu = 0.5, double cv = 0.5, double reach = 10,
                    int max_iterations = 40, double *last = nullptr, const Jet *start = nullptr) {
    for (int it = 0; it < max_iterations; ++it) {
      Jet j;
      if (it == 0 && start) {
        j = *start;
      } else {
        gradient_at(u, v, j.g);
        hessian_at(u, v, j.h);
      }
      const double fu = j.g[0], fv = j.g[1], a = j.h[0], b = j.h[1], c = j.h[2];
      const double det = a * c - b * b;
      if (!(std::abs(det) > 0))
        return false;
      const double du = (c * fu - b * fv) / det, dv = (a * fv - b * fu) / det;
      u -= du;
      v -= dv;
      if (last)
        *last = std::abs(du) + std::abs(dv);
      if (!std::isfinite(u) || !std::isfinite(v) || std::abs(u - cu) > reach ||
          std::abs(v - cv) > reach)
        return false;
      if (std::abs(du) + std::abs(dv) <= 4 * eps * (1 + std::abs(u) + std::abs(v)))
        return true;
    }
    return true;
  };

  // Krawczyk on boxes centred at (cx, cy) around the point (x, y) inside them: what does not
  // depend on the box's half-widths, computed once (the Hessian's entries expanded at the
  // centre into taylor_store, so one preparation is live at a time).
  struct KrawczykAt {
    bool usable = false; // the Hessian at (x, y) is invertible
    double cx, cy, x, y, y00, y01, y10, y11;
    Taylor huu, huv, hvv;
    Iv F0, F1;
  };
  auto krawczyk_at = [&](double cx, double cy, double x, double y) {
    KrawczykAt k;
    double h[3];
    hessian_at(x, y, h);
    const double a = h[0], b = h[1], c = h[2];
    const double det = a * c - b * b;
    if (!(std::abs(det) > 0) || !std::isfinite(det))
      return k;
    k.usable = true;
    k.cx = cx;
    k.cy = cy;
    k.x = x;
    k.y = y;
    k.y00 = c / det;
    k.y01 = -b / det;
    k.y10 = -b / det;
    k.y11 = a / det;
    // M = I - Y J(X), each entry enclosed as one polynomial (the combination of the Hessian's
    // entries formed first): entry-wise intervals of J(X) lose the cancellation in Y J(X), which
    // for an ill-conditioned Hessian (thin cells) leaves M far from contracting on any box.
    // The Hessian's entries expanded once at the centre; each entry of M is a combination.
    k.huu = expand(muu, cx, cy, taylor_store);
    k.huv = expand(muv, cx, cy, taylor_store + hsz);
    k.hvv = expand(mvv, cx, cy, taylor_store + 2 * hsz);
    double f[2], fa[2];
    gradient_at(x, y, f);
    evaluate<true, 2>(gradient, x, y, fa);
    const double eu = err_u + mu.error_bound_of(fa[0]), ev = err_v + mv.error_bound_of(fa[1]);
    k.F0 = {f[0] - eu, f[0] + eu};
    k.F1 = {f[1] - ev, f[1] + ev};
    return k;
  };
  // The test on the box with half-widths (rx, ry): 1 = a unique zero in the box, -1 = no zero
  // in the box, 0 = undecided.
  auto krawczyk_test = [&](const KrawczykAt &k, double rx, double ry) {
    if (!k.usable)
      return 0;
    const double cx = k.cx, cy = k.cy, x = k.x, y = k.y;
    const Iv M00 = Iv{1, 1} + (-1.0) * combination_range(k.y00, k.huu, k.y01, k.huv, rx, ry);
    const Iv M01 = (-1.0) * combination_range(k.y00, k.huv, k.y01, k.hvv, rx, ry);
    const Iv M10 = (-1.0) * combination_range(k.y10, k.huu, k.y11, k.huv, rx, ry);
    const Iv M11 = Iv{1, 1} + (-1.0) * combination_range(k.y10, k.huv, k.y11, k.hvv, rx, ry);
    const Iv D0{cx - rx - x, cx + rx - x}, D1{cy - ry - y, cy + ry - y};
    const Iv K0 = Iv{x, x} + (-1.0) * (k.y00 * k.F0 + k.y01 * k.F1) + M00 * D0 + M01 * D1;
    const Iv K1 = Iv{y, y} + (-1.0) * (k.y10 * k.F0 + k.y11 * k.F1) + M10 * D0 + M11 * D1;
    const double slack = 8 * eps * (1 + std::abs(x) + std::abs(y));
    if (K0.hi + slack < cx - rx || K0.lo - slack > cx + rx || K1.hi + slack < cy - ry ||
        K1.lo - slack > cy + ry)
      return -1;
    if (K0.lo - slack > cx - rx && K0.hi + slack < cx + rx && K1.lo - slack > cy - ry &&
        K1.hi + slack < cy + ry)
      return 1;
    return 0;
  };
  // Both at once, for a single box centred at (cx, cy) with half-widths (rx, ry).
  auto krawczyk = [&](double cx, double cy, double rx, double ry, double x, double y) {
    return krawczyk_test(krawczyk_at(cx, cy, x, y), rx, ry);
  };

  struct Found {
    double u, v, cx, cy, rx, ry;
    bool certified;
  };
  thread_local std::vector<Found> found;
  found.clear();
  // Grows the certified box f around the zero (x, y) while Krawczyk still proves uniqueness:
  // the larger it is, the fewer boxes around the zero need subdividing. A box centred at the
  // zero with twice f's largest radius contains f.
  auto grown = [&](double x, double y, Found f) {
    const KrawczykAt k = krawczyk_at(x, y, x, y);
    for (double R = 2 * std::max(f.rx, f.ry); R <= 0.5 && krawczyk_test(k, R, R) == 1; R *= 2)
      f = {x, y, x, y, R, R, true};
    return f;
  };
  auto known = [&](double u, double v) {
    for (const Found &f : found)
      if (f.certified && std::abs(u - f.cx) <= f.rx && std::abs(v - f.cy) <= f.ry)
        return true;
    return false;
  };

  // Depth-first subdivision; boxes and their coefficients live on two stacks reused across
  // calls of the same thread (no allocation per box).
  thread_local std::vector<Box> stack;
  thread_local std::vector<double> arena, current;
  stack.clear();
  arena.assign(2 * sz, 0.0);
  current.resize(2 * sz);
  if (framed) {
    // Tensor coefficients on the cell's bounding rectangle: the monomials in its local
    // parameters p = x / root_w, q = y / root_h.
    thread_local std::vector<double> scaled;
    for (const Monomial *c : {&mu, &mv}) {
      scaled.assign(c->a, c->a + sz);
      for (int i = 0; i <= m; ++i)
        for (int j = 0; i + j <= m; ++j)
          scaled[static_cast<std::size_t>(i) * (m + 1) + j] *=
              std::pow(root_w, i) * std::pow(root_h, j);
      TensorBernstein::from_monomial(scaled.data(), m, arena.data() + (c == &mv ? sz : 0));
    }
  } else {
    TensorBernstein::from_monomial(mu.a, m, arena.data());
    TensorBernstein::from_monomial(mv.a, m, arena.data() + sz);
  }
  stack.push_back({0.0, 0.0, root_w, root_h, 0});
  // Bounds on the rounding of the subdivided coefficients (conversion and de Casteljau steps),
  // so that a sign test never excludes a box on rounding noise.
  double mp = 0, mq = 0;
  for (std::size_t i = 0; i < sz; ++i) {
    mp = std::max(mp, std::abs(arena[i]));
    mq = std::max(mq, std::abs(arena[sz + i]));
  }
  if (framed) {
    // Each component with its own noise level (they differ by the cell's aspect ratio).
    mp = err_u + 64 * (m + 1) * (m + 1) * eps * mp;
    mq = err_v + 64 * (m + 1) * (m + 1) * eps * mq;
  } else {
    // One level for both components: a component whose coefficients are all at the noise level
    // of the gradient gives no certified sign.
    mp = mq = 64 * (m + 1) * (m + 1) * eps * std::max(mp, mq);
  }
  const double tol = opt.boundary_tolerance;
  // A box entirely outside the triangle (beyond the tolerance): all four corners beyond one of
  // its sides u = 0, v = 0, u + v = 1.
  auto outside = [&](const Box &b) {
    if (!framed)
      return b.u0 + b.v0 > 1 + tol;
    bool out_u = true, out_v = true, out_w = true;
    for (int k = 0; k < 4; ++k) {
      const Vec2 p = to_reference(b.u0 + (k & 1) * b.w, b.v0 + (k >> 1) * b.wy);
      out_u = out_u && p[0] < -tol;
      out_v = out_v && p[1] < -tol;
      out_w = out_w && p[0] + p[1] > 1 + tol;
    }
    return out_u || out_v || out_w;
  };
  // A box inside one of the excluded squares (all four corners, in reference coordinates).
  auto excluded = [&](const Box &b) {
    for (const auto &sq : opt.excluded) {
      bool inside = true;
      for (int k = 0; k < 4 && inside; ++k) {
        const double bu = b.u0 + (k & 1) * b.w, bv = b.v0 + (k >> 1) * b.wy;
        const Vec2 p = framed ? to_reference(bu, bv) : Vec2{bu, bv};
        inside = std::abs(p[0] - sq[0]) <= sq[2] && std::abs(p[1] - sq[1]) <= sq[2];
      }
      if (inside)
        return true;
    }
    return false;
  };
  int64_t deep = 0;
  while (!stack.empty()) {
    const Box b = stack.back();
    stack.pop_back();
    std::copy(arena.begin() + static_cast<std::ptrdiff_t>(b.offset),
              arena.begin() + static_cast<std::ptrdiff_t>(b.offset + 2 * sz), current.begin());
    arena.resize(b.offset);
    if (++out.boxes > budget) {
      out.budget_exhausted = true;
      break;
    }
    if (outside(b) || (!opt.excluded.empty() && excluded(b)))
      continue;
    if (excludes_zero(current.data(), sz, mp) || excludes_zero(current.data() + sz, sz, mq))
      continue;
    const double hx = 0.5 * b.w, hy = 0.5 * b.wy, wmax = std::max(b.w, b.wy);
    const double cx = b.u0 + hx, cy = b.v0 + hy;
    Jet centre;
    gradient_at(cx, cy, centre.g);
    if (combination_excludes_zero(current.data(), current.data() + sz, sz, centre.g[0], centre.g[1],
                                  mp, mq))
      continue;
    // Preconditioned by the inverse Hessian at the centre: near a zero the rows of H^-1 grad
    // behave like u - u* and v - v*, so one of them keeps a sign on a box that misses the zero
    // even where the components' zero curves are nearly parallel (thin cells in the reference
    // triangle, ill-conditioned Hessians).
    {
      hessian_at(cx, cy, centre.h);
      const double a = centre.h[0], bb = centre.h[1], c = centre.h[2];
      const double det = a * c - bb * bb;
      if (std::isfinite(det) && std::abs(det) > 0 &&
          (combination_excludes_zero(current.data(), current.data() + sz, sz, c, -bb, mp, mq) ||
           combination_excludes_zero(current.data(), current.data() + sz, sz, -bb, a, mp, mq)))
        continue;
    }
    // Inside a box where Krawczyk already proved a unique zero (found and recorded): nothing
    // else to find here.
    bool covered = false;
    for (const Found &f : found)
      covered = covered || (f.certified && b.u0 >= f.cx - f.rx && b.u0 + b.w <= f.cx + f.rx &&
                            b.v0 >= f.cy - f.ry && b.v0 + b.wy <= f.cy + f.ry);
    if (covered)
      continue;
    // Newton first, on boxes up to half the square (not the root, where the screen has just
    // failed and a single zero rarely certifies a box that large): three steps from the centre;
    // if they converge (the last below a thousandth of the box), Krawczyk on the square centred
    // at the limit z that covers the box. Success proves z the only zero in that square: the box
    // holds z or nothing, and the certified square may already cover its neighbours.
    const bool stepped = !framed && wmax <= 0.5;
    bool stepped_ok = false; // the three steps neither failed nor left the reach
    if (stepped) {
      double x = cx, y = cy, last = INFINITY;
      stepped_ok = newton(x, y, cx, cy, 2 * wmax, 3, &last, &centre);
      if (stepped_ok && last <= 1e-3 * wmax) {
        const double R = 1.0625 * std::max(std::abs(x - cx) + hx, std::abs(y - cy) + hy);
        if (krawczyk(x, y, R, R, x, y) == 1) {
          newton(x, y); // converges inside the square (Krawczyk)
          if (!known(x, y))
            found.push_back(grown(x, y, {x, y, x, y, R, R, true}));
          continue;
        }
      }
    }
    // Krawczyk on the box itself, around the point three Newton steps from the centre reach if
    // it stays in the box, else the centre. Not where the steps above succeeded: this adds
    // next to nothing to the attempt around their limit (it is hardly ever decisive there), and
    // the box is split. Where they failed, the same steps with a smaller reach fail too: the
    // centre.
    if (wmax <= 0.25 && !stepped_ok) {
      // Certify on the box inflated by a quarter, so zeros on box edges are interior.
      const double rx = 1.25 * hx, ry = 1.25 * hy, r = std::max(rx, ry);
      double x = cx, y = cy;
      if (stepped || !newton(x, y, cx, cy, 2 * r, 3, nullptr, &centre) || std::abs(x - cx) > rx ||
          std::abs(y - cy) > ry) {
        x = cx;
        y = cy;
      }
      const int k = krawczyk(cx, cy, rx, ry, x, y);
      if (k == -1)
        continue;
      if (k == 1) {
        newton(x, y); // converges inside the box (Krawczyk)
        if (!known(x, y))
          found.push_back(grown(x, y, {x, y, cx, cy, rx, ry, true}));
        continue;
      }
    }
    if (wmax <= opt.deep_width && ++deep > opt.deep_limit) {
      out.budget_exhausted = true;
      out.stopped_at = framed ? to_reference(cx, cy) : Vec2{cx, cy};
      break;
    }
    if (wmax <= opt.resolution) {
      found.push_back({cx, cy, cx, cy, hx, hy, false});
      continue;
    }
    // A framed search starts on a rectangle: boxes more than twice as long as wide are halved
    // across their length until they are nearly square.
    if (b.w > 2 * b.wy || b.wy > 2 * b.w) {
      const bool along_u = b.w > b.wy;
      const std::size_t base = arena.size();
      arena.resize(base + 4 * sz);
      for (int part = 0; part < 2; ++part) {
        double *h[2] = {arena.data() + base + 2 * sz + part * sz, arena.data() + base + part * sz};
        TensorBernstein::split_halves(current.data() + part * sz, m, m, along_u, h);
      }
      // The upper half at base, the lower at base + 2 sz (examined next).
      stack.push_back(along_u ? Box{b.u0 + hx, b.v0, hx, b.wy, base}
                              : Box{b.u0, b.v0 + hy, b.w, hy, base});
      stack.push_back(along_u ? Box{b.u0, b.v0, hx, b.wy, base + 2 * sz}
                              : Box{b.u0, b.v0, b.w, hy, base + 2 * sz});
      continue;
    }
    // Children k = 3..0 on top of the stacks (k = 0 is examined next).
    const std::size_t base = arena.size();
    arena.resize(base + 8 * sz);
    for (int part = 0; part < 2; ++part) {
      double *q[4];
      for (int k = 0; k < 4; ++k)
        q[k] = arena.data() + base + static_cast<std::size_t>(3 - k) * 2 * sz + part * sz;
      TensorBernstein::split_quarters(current.data() + part * sz, m, m, q);
    }
    for (int k = 3; k >= 0; --k)
      stack.push_back({b.u0 + (k & 1) * hx, b.v0 + (k >> 1) * hy, hx, hy,
                       base + static_cast<std::size_t>(3 - k) * 2 * sz});
  }

  // Keep zeros in the closed triangle (within tolerance); merge unresolved neighbours.
  // Box coordinates -> reference triangle; a box's half-width becomes at most |B| times it.
  const double bnorm =
      std::max(std::abs(B[0][0]) + std::abs(B[0][1]), std::abs(B[1][0]) + std::abs(B[1][1]));
  for (Found &f : found) {
    const Vec2 r = to_reference(f.u, f.v);
    f.u = r[0];
    f.v = r[1];
    f.rx *= bnorm;
    f.ry *= bnorm;
  }
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

} // namespace

} // namespace hoct
