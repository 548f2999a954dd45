#include "poly/root_isolation.hpp"

#include "poly/degree_dispatch.hpp"
#include "util/no_vectorize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {
namespace {

int sign(double x) { return (x > 0) - (x < 0); }

// Sign changes of c[0..n] (zeros skipped).
int sign_changes(const double *c, int n) {
  return bernstein_sign_changes({c, static_cast<std::size_t>(n) + 1});
}

// The sign of q just inside its left (or right) end: its first (last) non-zero coefficient.
int end_sign(const double *c, int n, bool left) {
  if (left) {
    for (int i = 0; i <= n; ++i)
      if (c[i] != 0)
        return sign(c[i]);
  } else {
    for (int i = n; i >= 0; --i)
      if (c[i] != 0)
        return sign(c[i]);
  }
  return 0;
}

// value_and_slope below for a compile-time degree M >= 1. Scalar (util/no_vectorize.hpp), as
// bernstein_value.
template <int M>
HOCT_NO_VECTORIZE void value_and_slope_fixed(const double *c, double s, double t, double &value,
                                             double &slope) {
  double w[M + 1];
  for (int i = 0; i <= M; ++i)
    w[i] = c[i];
  for (int r = 1; r < M; ++r)
    for (int i = 0; i <= M - r; ++i)
      w[i] = s * w[i] + t * w[i + 1];
  value = s * w[0] + t * w[1];
  slope = M * (w[1] - w[0]);
}

// p(t) and p'(t) in one de Casteljau pass: the last two intermediate values give the derivative.
// In registers for the usual degrees (the same operations as the run-time loop).
void value_and_slope(const double *c, int n, double t, double &value, double &slope) {
  if (n == 0) {
    value = c[0];
    slope = 0;
    return;
  }
  const double s = 1.0 - t;
  dispatch_degree(n, [&](auto D) {
    if constexpr (D.value >= 1) {
      value_and_slope_fixed<D.value>(c, s, t, value, slope);
    } else { // a stack buffer up to degree 31, the heap only above
      double buf[32];
      std::vector<double> heap;
      double *w = buf;
      if (n + 1 > 32) {
        heap.assign(c, c + n + 1);
        w = heap.data();
      } else {
        std::copy(c, c + n + 1, w);
      }
      for (int r = 1; r < n; ++r)
        for (int i = 0; i <= n - r; ++i)
          w[i] = s * w[i] + t * w[i + 1];
      value = s * w[0] + t * w[1];
      slope = n * (w[1] - w[0]);
    }
  });
}

// The single root of p in (lo, hi), with p of sign `slo` just right of lo: safeguarded Newton
// (bisection whenever a step leaves the bracket).
double refine_simple(const double *c, int n, double lo, double hi, int slo) {
  double x = 0.5 * (lo + hi);
  if (n <= 2) {
    // Linear and quadratic (the edge derivatives of quadratic and cubic fields): the root in
    // closed form (the quadratic by the cancellation-free formula), which Newton then confirms
    // in a step or two. A start outside the bracket (rounding at its ends) is not taken.
    const double a = n == 2 ? c[0] - 2 * c[1] + c[2] : 0.0;
    const double b = n == 2 ? 2 * (c[1] - c[0]) : c[1] - c[0];
    double r[2] = {-c[0] / b, -c[0] / b};
    if (a != 0) {
      const double disc = b * b - 4 * a * c[0];
      const double q = -0.5 * (b + std::copysign(std::sqrt(std::max(disc, 0.0)), b));
      r[0] = q / a;
      r[1] = c[0] / q;
    }
    for (double t : r)
      if (t > lo && t < hi) {
        x = t;
        break;
      }
  } else if (lo == 0.0 && hi == 1.0) {
    // Start where the control polygon crosses zero (its first sign change): close to the root,
    // so Newton needs few steps.
    for (int i = 0; i < n; ++i)
      if ((c[i] > 0 && c[i + 1] < 0) || (c[i] < 0 && c[i + 1] > 0)) {
        const double t = (i + c[i] / (c[i] - c[i + 1])) / n;
        if (t > 0 && t < 1)
          x = t;
        break;
      }
  }
  for (int it = 0; it < 300; ++it) {
    double fx, d;
    value_and_slope(c, n, x, fx, d);
    if (fx == 0)
      return x;
    if (sign(fx) == slo)
      lo = x;
    else
      hi = x;
    double next = d != 0 ? x - fx / d : 0.5 * (lo + hi);
    // Converged: the Newton step is at the last bits of x (it may round back onto x, the end
    // of the bracket), or the bracket is that narrow.
    const double ulp = 2 * std::numeric_limits<double>::epsilon() * std::abs(x);
    if (std::abs(next - x) <= ulp || hi - lo <= ulp)
      return x;
    if (!(next > lo && next < hi))
      next = 0.5 * (lo + hi);
    x = next;
  }
  return x;
}

// Roots found by sign changes alone (no tangency check), appended to `roots` (empty on entry).
// The subdivision keeps its intervals' coefficients on a per-thread stack: no allocation per
// call once the thread's buffers have grown.
void sign_change_roots(const double *p, int n, const RootOptions &opt, bool *identically_zero,
                       std::vector<Root> &roots) {
  const bool zero_poly = std::all_of(p, p + n + 1, [](double c) { return c == 0; });
  if (identically_zero)
    *identically_zero = zero_poly;
  if (zero_poly || n < 1)
    return;
  const std::size_t first = roots.size(); // sorted and merged from here on
  // Descartes: no sign change and non-zero ends, no root (the common case).
  const int changes = sign_changes(p, n);
  if (p[0] != 0 && p[n] != 0 && changes == 0)
    return;
  auto exact_root = [&](double t) {
    double value, slope;
    value_and_slope(p, n, t, value, slope);
    const bool simple = slope != 0;
    roots.push_back({t, t, t, simple, simple ? 1 : 2});
  };
  if (p[0] == 0)
    exact_root(0.0);
  if (p[n] == 0)
    exact_root(1.0);
  // One sign change: exactly one root in (0, 1), simple (the common case, no subdivision).
  if (p[0] != 0 && p[n] != 0 && changes == 1) {
    roots.push_back({refine_simple(p, n, 0.0, 1.0, sign(p[0])), 0.0, 1.0, true, 1});
    return;
  }
  struct Interval {
    double a, b;
    std::size_t offset; // its coefficients (p reparameterised to [a, b]) in the arena
  };
  const std::size_t len = static_cast<std::size_t>(n) + 1;
  thread_local std::vector<Interval> stack;
  thread_local std::vector<double> arena, w;
  stack.clear();
  arena.assign(p, p + len);
  w.resize(len);
  stack.push_back({0.0, 1.0, 0});
  while (!stack.empty()) {
    const Interval iv = stack.back();
    stack.pop_back();
    // The top interval's coefficients are the arena's last ones: take them off.
    std::copy(arena.begin() + static_cast<std::ptrdiff_t>(iv.offset),
              arena.begin() + static_cast<std::ptrdiff_t>(iv.offset + len), w.begin());
    arena.resize(iv.offset);
    // Sign changes of the coefficients, zeros skipped: exact zeros at the ends are roots recorded
    // separately, not roots in the open interval.
    const int v = sign_changes(w.data(), n);
    if (v == 0)
      continue;
    if (v == 1) {
      const double t = refine_simple(p, n, iv.a, iv.b, end_sign(w.data(), n, true));
      roots.push_back({t, iv.a, iv.b, true, 1});
      continue;
    }
    if (iv.b - iv.a <= opt.resolution) {
      roots.push_back({0.5 * (iv.a + iv.b), iv.a, iv.b, false, v});
      continue;
    }
    // Split at 1/2 (de Casteljau, as BernsteinPoly::split): the right half below the left on
    // the stack, so the left is examined next.
    const double m = 0.5 * (iv.a + iv.b);
    const std::size_t right_at = arena.size(), left_at = right_at + len;
    arena.resize(right_at + 2 * len);
    double *left = arena.data() + left_at, *right = arena.data() + right_at;
    left[0] = w[0];
    right[n] = w[n];
    for (int r = 1; r <= n; ++r) {
      for (int i = 0; i <= n - r; ++i)
        w[i] = (1.0 - 0.5) * w[i] + 0.5 * w[i + 1];
      left[r] = w[0];
      right[n - r] = w[n - r];
    }
    if (right[0] == 0)
      exact_root(m);
    stack.push_back({m, iv.b, right_at});
    stack.push_back({iv.a, m, left_at});
  }
  std::sort(roots.begin() + static_cast<std::ptrdiff_t>(first), roots.end(),
            [](const Root &x, const Root &y) { return x.t < y.t; });
  // Roots closer than the cluster distance, and clusters that touch, are one cluster (merged
  // in place).
  std::size_t kept = first;
  for (std::size_t i = first; i < roots.size(); ++i) {
    const Root r = roots[i];
    if (kept > first) {
      Root &m = roots[kept - 1];
      if (r.t - m.t < opt.cluster_distance || (!r.simple && !m.simple && r.lo <= m.hi)) {
        m.lo = std::min(m.lo, r.lo);
        m.hi = std::max(m.hi, r.hi);
        m.t = 0.5 * (m.lo + m.hi);
        m.simple = false;
        m.multiplicity += r.multiplicity;
        continue;
      }
    }
    roots[kept++] = r;
  }
  roots.resize(kept);
}

} // namespace

bool certainly_rootless(std::span<const double> c, const RootOptions &opt) {
  if (c.empty())
    return false;
  double scale = 0, lo = c[0], hi = c[0];
  for (double x : c) {
    scale = std::max(scale, std::abs(x));
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return certainly_rootless(lo, hi, scale, opt);
}

bool certainly_rootless(double lo, double hi, double scale, const RootOptions &opt) {
  const double level = std::max(opt.near_zero, 0.0) * scale;
  return scale > 0 && (lo > level || hi < -level);
}

std::vector<Root> find_roots(const BernsteinPoly &p, const RootOptions &opt,
                             bool *identically_zero) {
  std::vector<Root> roots;
  find_roots(p.coefficients(), roots, opt, identically_zero);
  return roots;
}

void find_roots(std::span<const double> c, std::vector<Root> &roots, const RootOptions &opt,
                bool *identically_zero) {
  roots.clear();
  if (c.empty()) { // no coefficients: the zero polynomial
    if (identically_zero)
      *identically_zero = true;
    return;
  }
  // No sign change and no tangency possible (the threshold test below, done first).
  if (certainly_rootless(c, opt)) {
    if (identically_zero)
      *identically_zero = false;
    return;
  }
  const int n = static_cast<int>(c.size()) - 1;
  sign_change_roots(c.data(), n, opt, identically_zero, roots);
  if (opt.near_zero <= 0 || n < 2 || (identically_zero && *identically_zero))
    return;
  // One sign change over all of [0, 1]: by Descartes exactly one root there, simple, and every
  // tangency the check below could find lies in its interval (it would add nothing).
  if (roots.size() == 1 && roots[0].lo == 0.0 && roots[0].hi == 1.0 && roots[0].simple)
    return;
  double scale = 0, lo = c[0], hi = c[0];
  for (double x : c) {
    scale = std::max(scale, std::abs(x));
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (scale == 0)
    return;
  // p(t) lies between its smallest and largest coefficient: if those keep |p| above the
  // tangency threshold, no double root can hide anywhere on [0, 1].
  if (lo > opt.near_zero * scale || hi < -opt.near_zero * scale)
    return;
  RootOptions inner = opt;
  inner.near_zero = 0;
  thread_local std::vector<double> dp;
  thread_local std::vector<Root> tangencies;
  dp.resize(static_cast<std::size_t>(n));
  bernstein_derivative(c, dp.data());
  tangencies.clear();
  sign_change_roots(dp.data(), n - 1, inner, nullptr, tangencies);
  bool added = false;
  for (const Root &s : tangencies) {
    if (!(std::abs(bernstein_value(c, s.t)) <= opt.near_zero * scale))
      continue;
    bool known = false;
    for (const Root &r : roots)
      known = known || std::abs(r.t - s.t) < opt.cluster_distance || (s.t >= r.lo && s.t <= r.hi);
    if (!known) {
      roots.push_back({s.t, s.lo, s.hi, false, 2});
      added = true;
    }
  }
  if (added)
    std::sort(roots.begin(), roots.end(), [](const Root &x, const Root &y) { return x.t < y.t; });
  // A tangency next to a found root makes that root non-simple.
  for (std::size_t i = 0; i + 1 < roots.size(); ++i)
    if (roots[i + 1].t - roots[i].t < opt.cluster_distance)
      roots[i].simple = roots[i + 1].simple = false;
}

} // namespace hoct
