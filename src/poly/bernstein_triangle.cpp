#include "poly/bernstein_triangle.hpp"

#include "poly/binomial.hpp"
#include "poly/degree_dispatch.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace hoct {
namespace {} // namespace

BernsteinTriangle::BernsteinTriangle(int degree, std::vector<double> coefficients)
    : d_(degree), c_(std::move(coefficients)) {
  if (degree < 0 || static_cast<int>(c_.size()) != lattice_size(degree))
    throw std::invalid_argument("BernsteinTriangle: coefficient count does not match degree");
}

BernsteinTriangle::BernsteinTriangle(int degree)
    : d_(degree), c_(static_cast<std::size_t>(lattice_size(degree)), 0.0) {}

namespace {

// A working copy of coefficients for de Casteljau in place: on the stack up to degree 12 (no
// allocation), else on the heap.
struct WorkCopy {
  explicit WorkCopy(std::span<const double> c) {
    if (c.size() > kStack) {
      heap.assign(c.begin(), c.end());
      w = heap.data();
    } else {
      std::copy(c.begin(), c.end(), stack);
    }
  }
  static constexpr std::size_t kStack = 91; // lattice_size(12)
  double stack[kStack];
  std::vector<double> heap;
  double *w = stack;
};

// de Casteljau steps in place from degree `from` down to degree `to` at barycentric l: step n
// overwrites the lower-degree coefficients it no longer needs (index (a, b) in degree n-1 is <=
// index (a, b) in degree n, and the entries of degree n read later, (a+1, b) and (a, b+1), have
// larger indices).
// One in-place step for a compile-time degree N, fully unrolled: read from a local copy (the
// same values: a step never overwrites a coefficient it still has to read), so that the
// compiler sees no aliasing and emits straight-line code instead of runtime-checked loops.
template <int N>
inline __attribute__((always_inline)) void casteljau_step_fixed(double *w,
                                                                const std::array<double, 3> &l) {
  constexpr int size = lattice_size(N);
  double src[size];
#pragma GCC unroll 64
  for (int i = 0; i < size; ++i)
    src[i] = w[i];
  const double l0 = l[0], l1 = l[1], l2 = l[2];
#pragma GCC unroll 16
  for (int b = 0; b <= N - 1; ++b)
#pragma GCC unroll 16
    for (int a = 0; a <= N - 1 - b; ++a)
      w[lattice_index(N - 1, a, b)] = l0 * src[lattice_index(N, a, b)] +
                                      l1 * src[lattice_index(N, a + 1, b)] +
                                      l2 * src[lattice_index(N, a, b + 1)];
}

// Fixed-degree steps from degree N down to degree `to`.
template <int N> void casteljau_fixed_down(double *w, int to, const std::array<double, 3> &l) {
  if constexpr (N > 0) {
    if (N > to) {
      casteljau_step_fixed<N>(w, l);
      casteljau_fixed_down<N - 1>(w, to, l);
    }
  }
}

void casteljau_down(double *w, int from, int to, const std::array<double, 3> &l) {
  // The usual degrees (1 to 8), unrolled.
  const bool fixed = dispatch_degree(from, [&](auto D) {
    if constexpr (D.value >= 1 && D.value <= 8) {
      casteljau_fixed_down<D.value>(w, to, l);
      return true;
    }
    return false;
  });
  if (fixed)
    return;
  for (int n = from; n > to; --n)
    for (int b = 0; b <= n - 1; ++b)
      for (int a = 0; a <= n - 1 - b; ++a)
        w[lattice_index(n - 1, a, b)] = l[0] * w[lattice_index(n, a, b)] +
                                        l[1] * w[lattice_index(n, a + 1, b)] +
                                        l[2] * w[lattice_index(n, a, b + 1)];
}

} // namespace

double BernsteinTriangle::operator()(double u, double v) const {
  WorkCopy work(c_);
  casteljau_down(work.w, d_, 0, barycentric(u, v));
  return work.w[0];
}

BernsteinTriangle BernsteinTriangle::du() const {
  if (d_ == 0)
    return BernsteinTriangle(0);
  BernsteinTriangle r(d_ - 1);
  for (int b = 0; b <= d_ - 1; ++b)
    for (int a = 0; a <= d_ - 1 - b; ++a)
      r.c_[lattice_index(d_ - 1, a, b)] = d_ * (coefficient(a + 1, b) - coefficient(a, b));
  return r;
}

BernsteinTriangle BernsteinTriangle::dv() const {
  if (d_ == 0)
    return BernsteinTriangle(0);
  BernsteinTriangle r(d_ - 1);
  for (int b = 0; b <= d_ - 1; ++b)
    for (int a = 0; a <= d_ - 1 - b; ++a)
      r.c_[lattice_index(d_ - 1, a, b)] = d_ * (coefficient(a, b + 1) - coefficient(a, b));
  return r;
}

void BernsteinTriangle::assign(int degree, std::span<const double> coefficients) {
  if (degree < 0 || coefficients.size() != static_cast<std::size_t>(lattice_size(degree)))
    throw std::invalid_argument(
        "BernsteinTriangle::assign: coefficient count does not match the degree");
  d_ = degree;
  c_.assign(coefficients.begin(), coefficients.end());
}

BernsteinTriangle::Jet BernsteinTriangle::jet(double u, double v) const {
  return jet_of(c_, d_, u, v);
}

namespace {

// The jet from the degree-2 de Casteljau level w at barycentric l (w overwritten); Deg is the
// degree when known at compile time, else -1.
template <int Deg>
inline BernsteinTriangle::Jet jet_from_level(double *w, int run_time_degree,
                                             const std::array<double, 3> &l) {
  BernsteinTriangle::Jet j{0, {0, 0}, {{{0, 0}, {0, 0}}}};
  const int deg = Deg >= 0 ? Deg : run_time_degree;
  const double d = deg;
  if (deg >= 2) {
    auto q = [&](int a, int b) { return w[lattice_index(2, a, b)]; };
    const double s = d * (d - 1);
    j.hessian[0][0] = s * (q(2, 0) - 2 * q(1, 0) + q(0, 0));
    j.hessian[0][1] = j.hessian[1][0] = s * (q(1, 1) - q(1, 0) - q(0, 1) + q(0, 0));
    j.hessian[1][1] = s * (q(0, 2) - 2 * q(0, 1) + q(0, 0));
    for (int b = 0; b <= 1; ++b)
      for (int a = 0; a <= 1 - b; ++a)
        w[lattice_index(1, a, b)] = l[0] * q(a, b) + l[1] * q(a + 1, b) + l[2] * q(a, b + 1);
  }
  if (deg >= 1) {
    const double c0 = w[lattice_index(1, 0, 0)], c1 = w[lattice_index(1, 1, 0)],
                 c2 = w[lattice_index(1, 0, 1)];
    j.gradient = {d * (c1 - c0), d * (c2 - c0)};
    j.value = l[0] * c0 + l[1] * c1 + l[2] * c2;
  } else {
    j.value = w[0];
  }
  return j;
}

} // namespace

BernsteinTriangle::Jet BernsteinTriangle::jet_of(std::span<const double> c, int deg, double u,
                                                 double v) {
  const auto l = barycentric(u, v);
  // The usual degrees (1 to 8): the copy and the steps to degree 2 unrolled, in registers.
  return dispatch_degree(deg, [&](auto D) {
    if constexpr (D.value >= 1 && D.value <= 8) {
      double w[lattice_size(D.value)];
      for (int i = 0; i < lattice_size(D.value); ++i)
        w[i] = c[i];
      casteljau_fixed_down<D.value>(w, 2, l);
      return jet_from_level<D.value>(w, deg, l);
    } else {
      WorkCopy work(c);
      casteljau_down(work.w, deg, 2, l); // to degree 2: its coefficients give the Hessian
      return jet_from_level<-1>(work.w, deg, l);
    }
  });
}

Vec2 BernsteinTriangle::gradient(double u, double v) const { return {du()(u, v), dv()(u, v)}; }

Mat2 BernsteinTriangle::hessian(double u, double v) const {
  const BernsteinTriangle gu = du(), gv = dv();
  const double uu = gu.du()(u, v), uv = gu.dv()(u, v), vv = gv.dv()(u, v);
  return {{{uu, uv}, {uv, vv}}};
}

BernsteinPoly BernsteinTriangle::edge(int k) const {
  std::vector<double> e(d_ + 1);
  for (int t = 0; t <= d_; ++t) {
    switch (k) {
    case 0:
      e[t] = coefficient(t, 0);
      break;
    case 1:
      e[t] = coefficient(d_ - t, t);
      break;
    case 2:
      e[t] = coefficient(0, d_ - t);
      break;
    default:
      throw std::invalid_argument("BernsteinTriangle::edge: k must be 0, 1 or 2");
    }
  }
  return BernsteinPoly(std::move(e));
}

void BernsteinTriangle::set_edge(int k, const BernsteinPoly &p) {
  if (p.degree() != d_)
    throw std::invalid_argument("BernsteinTriangle::set_edge: degree mismatch");
  for (int t = 0; t <= d_; ++t) {
    switch (k) {
    case 0:
      c_[lattice_index(d_, t, 0)] = p[t];
      break;
    case 1:
      c_[lattice_index(d_, d_ - t, t)] = p[t];
      break;
    case 2:
      c_[lattice_index(d_, 0, d_ - t)] = p[t];
      break;
    default:
      throw std::invalid_argument("BernsteinTriangle::set_edge: k must be 0, 1 or 2");
    }
  }
}

namespace {

// One de Casteljau step from degree n to n - 1 in place (see operator()).
void casteljau_step_in_place(double *w, int n, const std::array<double, 3> &l) {
  for (int b = 0; b <= n - 1; ++b)
    for (int a = 0; a <= n - 1 - b; ++a)
      w[lattice_index(n - 1, a, b)] = l[0] * w[lattice_index(n, a, b)] +
                                      l[1] * w[lattice_index(n, a + 1, b)] +
                                      l[2] * w[lattice_index(n, a, b + 1)];
}

} // namespace

namespace {

// Steps from degree N down to 0 with weights l, in place; w[0] is the result.
template <int N> void casteljau_down(double *w, const std::array<double, 3> &l) {
  if constexpr (N > 0) {
    casteljau_step_fixed<N>(w, l);
    casteljau_down<N - 1>(w, l);
  }
}

// restrict_to_segment for a compile-time degree D: after K steps with p (in `level`), D-K steps
// with q give coefficient D-K.
template <int D, int K>
void restrict_fixed(double *level, const std::array<double, 3> &lp, const std::array<double, 3> &lq,
                    double *out) {
  constexpr int n0 = D - K;
  double work[lattice_size(n0)];
  for (int i = 0; i < lattice_size(n0); ++i)
    work[i] = level[i];
  casteljau_down<n0>(work, lq);
  out[n0] = work[0];
  if constexpr (K < D) {
    casteljau_step_fixed<n0>(level, lp);
    restrict_fixed<D, K + 1>(level, lp, lq, out);
  }
}

template <int D>
void restrict_fixed(const std::vector<double> &c, const std::array<double, 3> &lp,
                    const std::array<double, 3> &lq, double *out) {
  double level[lattice_size(D)];
  for (int i = 0; i < lattice_size(D); ++i)
    level[i] = c[i];
  restrict_fixed<D, 0>(level, lp, lq, out);
}

} // namespace

void BernsteinTriangle::restrict_to_segment(const Vec2 &p, const Vec2 &q, double *out) const {
  // Blossom: coefficient m = g[p^(d-m), q^m]. After k steps with p, d-k steps with q give
  // coefficient d-k.
  const auto lp = barycentric(p[0], p[1]);
  const auto lq = barycentric(q[0], q[1]);
  // The usual degrees (1 to 8), unrolled.
  const bool fixed = dispatch_degree(d_, [&](auto D) {
    if constexpr (D.value >= 1 && D.value <= 8) {
      restrict_fixed<D.value>(c_, lp, lq, out);
      return true;
    }
    return false;
  });
  if (fixed)
    return;
  constexpr int kStack = 91; // lattice_size(12)
  double level_buf[kStack], work_buf[kStack];
  std::vector<double> heap;
  double *level = level_buf, *work = work_buf;
  if (c_.size() > kStack) {
    heap.resize(2 * c_.size());
    level = heap.data();
    work = heap.data() + c_.size();
  }
  std::copy(c_.begin(), c_.end(), level);
  for (int k = 0; k <= d_; ++k) {
    const int n0 = d_ - k;
    std::copy(level, level + lattice_size(n0), work);
    for (int n = n0; n > 0; --n)
      casteljau_step_in_place(work, n, lq);
    out[n0] = work[0];
    if (k < d_)
      casteljau_step_in_place(level, n0, lp);
  }
}

BernsteinPoly BernsteinTriangle::restrict_to_segment(const Vec2 &p, const Vec2 &q) const {
  std::vector<double> out(d_ + 1);
  restrict_to_segment(p, q, out.data());
  return BernsteinPoly(std::move(out));
}

BernsteinTriangle BernsteinTriangle::elevated(int target) const {
  if (target < d_)
    throw std::invalid_argument("BernsteinTriangle::elevated: target below degree");
  BernsteinTriangle cur = *this;
  for (int n = d_; n < target; ++n) {
    BernsteinTriangle next(n + 1);
    for (int b = 0; b <= n + 1; ++b)
      for (int a = 0; a <= n + 1 - b; ++a) {
        const int k = n + 1 - a - b;
        double s = 0.0;
        if (k > 0)
          s += k * cur.coefficient(a, b);
        if (a > 0)
          s += a * cur.coefficient(a - 1, b);
        if (b > 0)
          s += b * cur.coefficient(a, b - 1);
        next.c_[lattice_index(n + 1, a, b)] = s / (n + 1);
      }
    cur = std::move(next);
  }
  return cur;
}

BernsteinTriangle BernsteinTriangle::operator*(const BernsteinTriangle &o) const {
  const int n = d_ + o.d_;
  BernsteinTriangle r(n);
  // The other factor's coefficients times their trinomials, once (on the stack up to degree 10).
  const std::size_t m = o.c_.size();
  std::array<double, 66> small;
  std::vector<double> large(m > small.size() ? m : 0);
  double *w2 = m > small.size() ? large.data() : small.data();
  for (int b2 = 0; b2 <= o.d_; ++b2)
    for (int a2 = 0; a2 <= o.d_ - b2; ++a2)
      w2[lattice_index(o.d_, a2, b2)] = trinomial(o.d_ - a2 - b2, a2, b2) * o.coefficient(a2, b2);
  // Every product accumulated in the same order as term by term: row b1 + b2 of the result
  // from a1 + a2 = a1 on.
  for (int b1 = 0; b1 <= d_; ++b1)
    for (int a1 = 0; a1 <= d_ - b1; ++a1) {
      const double w1 = trinomial(d_ - a1 - b1, a1, b1) * coefficient(a1, b1);
      for (int b2 = 0; b2 <= o.d_; ++b2) {
        double *out = &r.c_[lattice_index(n, a1, b1 + b2)];
        const double *in = &w2[lattice_index(o.d_, 0, b2)];
        for (int a2 = 0; a2 <= o.d_ - b2; ++a2)
          out[a2] += w1 * in[a2];
      }
    }
  for (int b = 0; b <= n; ++b)
    for (int a = 0; a <= n - b; ++a)
      r.c_[lattice_index(n, a, b)] /= trinomial(n - a - b, a, b);
  return r;
}

std::pair<double, double> BernsteinTriangle::bounds() const {
  auto [lo, hi] = std::minmax_element(c_.begin(), c_.end());
  return {*lo, *hi};
}

bool BernsteinTriangle::is_constant() const {
  return std::all_of(c_.begin(), c_.end(), [&](double x) { return x == c_[0]; });
}

BernsteinTriangle BernsteinTriangle::along(const Vec2 &e) const {
  BernsteinTriangle r = du();
  const BernsteinTriangle v = dv();
  for (std::size_t i = 0; i < r.c_.size(); ++i)
    r.c_[i] = e[0] * r.c_[i] + e[1] * v.c_[i];
  return r;
}

double BernsteinTriangle::gradient_scale() const {
  double s = 0;
  for (int b = 0; b < d_; ++b)
    for (int a = 0; a + b < d_; ++a) {
      const double x = coefficient(a, b);
      s = std::max(
          {s, d_ * std::abs(coefficient(a + 1, b) - x), d_ * std::abs(coefficient(a, b + 1) - x)});
    }
  return s;
}

void bernstein_from_lattice_values(const double *values, int degree, double *out) {
  // out[i] = sum over j of M(i, j) values[j], each a dot product taken in j order (the same
  // result to the bit), four rows at a time: a lone dot product waits on its previous addition
  // at every step, four independent ones fill those waits.
  const auto &m = lagrange_to_bernstein_triangle(degree);
  const int n = lattice_size(degree);
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const double *r0 = &m[static_cast<std::size_t>(i) * n], *r1 = r0 + n, *r2 = r1 + n,
                 *r3 = r2 + n;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (int j = 0; j < n; ++j) {
      const double v = values[j];
      s0 += r0[j] * v;
      s1 += r1[j] * v;
      s2 += r2[j] * v;
      s3 += r3[j] * v;
    }
    out[i] = s0;
    out[i + 1] = s1;
    out[i + 2] = s2;
    out[i + 3] = s3;
  }
  for (; i + 2 <= n; i += 2) {
    const double *r0 = &m[static_cast<std::size_t>(i) * n], *r1 = r0 + n;
    double s0 = 0.0, s1 = 0.0;
    for (int j = 0; j < n; ++j) {
      s0 += r0[j] * values[j];
      s1 += r1[j] * values[j];
    }
    out[i] = s0;
    out[i + 1] = s1;
  }
  for (; i < n; ++i) {
    const double *row = &m[static_cast<std::size_t>(i) * n];
    double s = 0.0;
    for (int j = 0; j < n; ++j)
      s += row[j] * values[j];
    out[i] = s;
  }
}

BernsteinTriangle bernstein_from_lattice_values(const double *values, int degree) {
  std::vector<double> c(lattice_size(degree));
  bernstein_from_lattice_values(values, degree, c.data());
  return BernsteinTriangle(degree, std::move(c));
}

} // namespace hoct
