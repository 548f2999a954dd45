#include "poly/bernstein_univariate.hpp"

#include "poly/binomial.hpp"
#include "poly/degree_dispatch.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "util/no_vectorize.hpp"

#include <algorithm>

namespace hoct {

namespace {

// de Casteljau in registers for a compile-time degree N (the same operations as the loop in
// bernstein_value). Scalar (util/no_vectorize.hpp): vectorised, its stack array stalls on store
// forwarding.
template <int N> HOCT_NO_VECTORIZE double value_fixed(const double *c, double s, double t) {
  double w[N + 1];
  for (int i = 0; i <= N; ++i)
    w[i] = c[i];
  for (int r = 1; r <= N; ++r)
    for (int i = 0; i <= N - r; ++i)
      w[i] = s * w[i] + t * w[i + 1];
  return w[0];
}

} // namespace

double bernstein_value(std::span<const double> c, double t) {
  if (c.empty())
    return 0.0;
  const int n = static_cast<int>(c.size()) - 1;
  const double s = 1.0 - t;
  return dispatch_degree(n, [&](auto D) {
    if constexpr (D.value >= 0) {
      return value_fixed<D.value>(c.data(), s, t);
    } else { // a stack buffer up to degree 31, the heap only above
      double buf[32];
      std::vector<double> heap;
      double *w = buf;
      if (n + 1 > 32) {
        heap.assign(c.begin(), c.end());
        w = heap.data();
      } else {
        std::copy(c.begin(), c.end(), w);
      }
      for (int r = 1; r <= n; ++r)
        for (int i = 0; i <= n - r; ++i)
          w[i] = s * w[i] + t * w[i + 1];
      return w[0];
    }
  });
}

void bernstein_derivative(std::span<const double> c, double *out) {
  const int n = static_cast<int>(c.size()) - 1;
  for (int i = 0; i < n; ++i)
    out[i] = n * (c[i + 1] - c[i]);
}

double BernsteinPoly::operator()(double t) const { return bernstein_value(c_, t); }

BernsteinPoly BernsteinPoly::derivative() const {
  const int n = degree();
  if (n <= 0)
    return BernsteinPoly(std::vector<double>{0.0});
  std::vector<double> d(n);
  bernstein_derivative(c_, d.data());
  return BernsteinPoly(std::move(d));
}

BernsteinPoly BernsteinPoly::reversed() const {
  std::vector<double> r(c_.rbegin(), c_.rend());
  return BernsteinPoly(std::move(r));
}

BernsteinPoly BernsteinPoly::elevated(int target) const {
  std::vector<double> cur = c_;
  for (int n = degree(); n < target; ++n) {
    // Elevation from degree n to n + 1.
    std::vector<double> next(n + 2);
    next[0] = cur[0];
    next[n + 1] = cur[n];
    for (int i = 1; i <= n; ++i) {
      const double a = static_cast<double>(i) / (n + 1);
      next[i] = a * cur[i - 1] + (1.0 - a) * cur[i];
    }
    cur.swap(next);
  }
  return BernsteinPoly(std::move(cur));
}

std::pair<BernsteinPoly, BernsteinPoly> BernsteinPoly::split(double t) const {
  const int n = degree();
  std::vector<double> w = c_, left(n + 1), right(n + 1);
  left[0] = w[0];
  right[n] = w[n];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i)
      w[i] = (1.0 - t) * w[i] + t * w[i + 1];
    left[r] = w[0];
    right[n - r] = w[n - r];
  }
  return {BernsteinPoly(std::move(left)), BernsteinPoly(std::move(right))};
}

BernsteinPoly BernsteinPoly::subinterval(double a, double b) const {
  // p on [a, 1] first, then cut that at the image of b.
  if (a <= 0.0 && b >= 1.0)
    return *this;
  BernsteinPoly right = a > 0.0 ? split(a).second : *this;
  if (b >= 1.0)
    return right;
  const double tb = a >= 1.0 ? 0.0 : (b - a) / (1.0 - a);
  return right.split(tb).first;
}

std::pair<double, double> BernsteinPoly::bounds() const {
  auto [lo, hi] = std::minmax_element(c_.begin(), c_.end());
  return {*lo, *hi};
}

int bernstein_sign_changes(std::span<const double> c) {
  int changes = 0, last = 0;
  for (double x : c) {
    const int s = (x > 0) - (x < 0);
    if (s == 0)
      continue;
    if (last != 0 && s != last)
      ++changes;
    last = s;
  }
  return changes;
}

int BernsteinPoly::sign_changes() const { return bernstein_sign_changes(c_); }

void bernstein_from_equispaced(const double *values, int degree, double *out) {
  const auto &m = lagrange_to_bernstein_1d(degree);
  const int n = degree + 1;
  for (int i = 0; i < n; ++i) {
    double s = 0.0;
    for (int j = 0; j < n; ++j)
      s += m[i * n + j] * values[j];
    out[i] = s;
  }
}

BernsteinPoly bernstein_from_equispaced(const double *values, int degree) {
  std::vector<double> c(degree + 1, 0.0);
  bernstein_from_equispaced(values, degree, c.data());
  return BernsteinPoly(std::move(c));
}

} // namespace hoct
