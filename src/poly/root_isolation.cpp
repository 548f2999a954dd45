#include "poly/root_isolation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {
namespace {

struct Interval {
  double a, b;
  BernsteinPoly p; // p reparameterised to [a, b]
};

int sign(double x) { return (x > 0) - (x < 0); }

// The sign of q just inside its left (or right) end: its first (last) non-zero coefficient.
int end_sign(const BernsteinPoly &q, bool left) {
  const auto &c = q.coefficients();
  if (left) {
    for (double x : c)
      if (x != 0)
        return sign(x);
  } else {
    for (auto it = c.rbegin(); it != c.rend(); ++it)
      if (*it != 0)
        return sign(*it);
  }
  return 0;
}

// p(t) and p'(t) in one de Casteljau pass: the last two intermediate values give the derivative.
void value_and_slope(const BernsteinPoly &p, double t, double &value, double &slope) {
  const int n = p.degree();
  const auto &c = p.coefficients();
  if (n == 0) {
    value = c[0];
    slope = 0;
    return;
  }
  double stack_buf[32];
  std::vector<double> heap;
  double *w = stack_buf;
  if (n + 1 > 32) {
    heap.assign(c.begin(), c.end());
    w = heap.data();
  } else {
    std::copy(c.begin(), c.end(), w);
  }
  const double s = 1.0 - t;
  for (int r = 1; r < n; ++r)
    for (int i = 0; i <= n - r; ++i)
      w[i] = s * w[i] + t * w[i + 1];
  value = s * w[0] + t * w[1];
  slope = n * (w[1] - w[0]);
}

// The single root of p in (lo, hi), with p of sign `slo` just right of lo: safeguarded Newton
// (bisection whenever a step leaves the bracket).
double refine_simple(const BernsteinPoly &p, double lo, double hi, int slo) {
  double x = 0.5 * (lo + hi);
  if (lo == 0.0 && hi == 1.0) {
    // Start where the control polygon crosses zero (its first sign change): close to the root,
    // so Newton needs few steps.
    const auto &c = p.coefficients();
    const int n = p.degree();
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
    value_and_slope(p, x, fx, d);
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

} // namespace

// Roots found by sign changes alone (no tangency check).
std::vector<Root> find_sign_change_roots(const BernsteinPoly &p, const RootOptions &opt,
                                         bool *identically_zero);

bool certainly_rootless(std::span<const double> c, const RootOptions &opt) {
  if (c.empty())
    return false;
  double scale = 0, lo = c[0], hi = c[0];
  for (double x : c) {
    scale = std::max(scale, std::abs(x));
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  const double level = std::max(opt.near_zero, 0.0) * scale;
  return scale > 0 && (lo > level || hi < -level);
}

std::vector<Root> find_roots(const BernsteinPoly &p, const RootOptions &opt,
                             bool *identically_zero) {
  // No sign change and no tangency possible (the threshold test below, done first).
  if (certainly_rootless(p.coefficients(), opt)) {
    if (identically_zero)
      *identically_zero = false;
    return {};
  }
  std::vector<Root> roots = find_sign_change_roots(p, opt, identically_zero);
  if (opt.near_zero <= 0 || p.degree() < 2 || (identically_zero && *identically_zero))
    return roots;
  double scale = 0, lo = p[0], hi = p[0];
  for (double c : p.coefficients()) {
    scale = std::max(scale, std::abs(c));
    lo = std::min(lo, c);
    hi = std::max(hi, c);
  }
  if (scale == 0)
    return roots;
  // p(t) lies between its smallest and largest coefficient: if those keep |p| above the
  // tangency threshold, no double root can hide anywhere on [0, 1].
  if (lo > opt.near_zero * scale || hi < -opt.near_zero * scale)
    return roots;
  RootOptions inner = opt;
  inner.near_zero = 0;
  const BernsteinPoly dp = p.derivative();
  bool added = false;
  for (const Root &s : find_sign_change_roots(dp, inner, nullptr)) {
    if (!(std::abs(p(s.t)) <= opt.near_zero * scale))
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
  return roots;
}

std::vector<Root> find_sign_change_roots(const BernsteinPoly &p, const RootOptions &opt,
                                         bool *identically_zero) {
  std::vector<Root> roots;
  const bool zero_poly = std::all_of(p.coefficients().begin(), p.coefficients().end(),
                                     [](double c) { return c == 0; });
  if (identically_zero)
    *identically_zero = zero_poly;
  if (zero_poly || p.degree() < 1)
    return roots;
  const int n = p.degree();
  // Descartes: no sign change and non-zero ends, no root (the common case, without allocating).
  if (p[0] != 0 && p[n] != 0 && p.sign_changes() == 0)
    return roots;
  auto exact_root = [&](double t) {
    double value, slope;
    value_and_slope(p, t, value, slope);
    const bool simple = slope != 0;
    roots.push_back({t, t, t, simple, simple ? 1 : 2});
  };
  if (p[0] == 0)
    exact_root(0.0);
  if (p[n] == 0)
    exact_root(1.0);
  // One sign change: exactly one root in (0, 1), simple (the common case, no subdivision).
  if (p[0] != 0 && p[n] != 0 && p.sign_changes() == 1) {
    roots.push_back({refine_simple(p, 0.0, 1.0, sign(p[0])), 0.0, 1.0, true, 1});
    return roots;
  }
  std::vector<Interval> stack;
  stack.push_back({0.0, 1.0, p});
  while (!stack.empty()) {
    Interval iv = std::move(stack.back());
    stack.pop_back();
    // Sign changes of the coefficients, zeros skipped: exact zeros at the ends are roots recorded
    // separately, not roots in the open interval.
    const int v = iv.p.sign_changes();
    if (v == 0)
      continue;
    if (v == 1) {
      const double t = refine_simple(p, iv.a, iv.b, end_sign(iv.p, true));
      roots.push_back({t, iv.a, iv.b, true, 1});
      continue;
    }
    if (iv.b - iv.a <= opt.resolution) {
      roots.push_back({0.5 * (iv.a + iv.b), iv.a, iv.b, false, v});
      continue;
    }
    const double m = 0.5 * (iv.a + iv.b);
    auto [left, right] = iv.p.split(0.5);
    if (right[0] == 0)
      exact_root(m);
    stack.push_back({m, iv.b, std::move(right)});
    stack.push_back({iv.a, m, std::move(left)});
  }
  std::sort(roots.begin(), roots.end(), [](const Root &x, const Root &y) { return x.t < y.t; });
  // Roots closer than the cluster distance, and clusters that touch, are one cluster.
  std::vector<Root> merged;
  for (const Root &r : roots) {
    if (!merged.empty() && (r.t - merged.back().t < opt.cluster_distance ||
                            (!r.simple && !merged.back().simple && r.lo <= merged.back().hi))) {
      Root &m = merged.back();
      m.lo = std::min(m.lo, r.lo);
      m.hi = std::max(m.hi, r.hi);
      m.t = 0.5 * (m.lo + m.hi);
      m.simple = false;
      m.multiplicity += r.multiplicity;
      continue;
    }
    merged.push_back(r);
  }
  return merged;
}

} // namespace hoct
