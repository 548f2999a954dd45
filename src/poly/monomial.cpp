#include "poly/monomial.hpp"

#include "poly/binomial.hpp"
#include "poly/degree_dispatch.hpp"
#include "poly/lattice.hpp"
#include "util/no_vectorize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {

std::vector<double> to_monomial(const BernsteinTriangle &p) {
  std::vector<double> mono((p.degree() + 1) * (p.degree() + 1));
  to_monomial(p.coefficients().data(), p.degree(), mono.data());
  return mono;
}

namespace {

template <int D> void to_monomial_fixed(const double *bernstein, int d_run, double *mono) {
  const int d = D >= 0 ? D : d_run;
  // The coefficient of u^i v^j is d! / (i! j! (d-i-j)!) times the forward difference
  // D_u^i D_v^j c_00 (D_u c_ab = c_(a+1)b - c_ab): the Bernstein lattice laid out in `mono`, then
  // differenced in place, first along v (each column a), then along u (each row j).
  const int w = d + 1;
  std::fill(mono, mono + w * w, 0.0);
  for (int b = 0; b <= d; ++b)
    for (int a = 0; a + b <= d; ++a)
      mono[a * w + b] = bernstein[lattice_index(d, a, b)];
  for (int a = 0; a <= d; ++a) {
    double *col = mono + a * w;
    for (int k = 1; k <= d - a; ++k)
      for (int b = d - a; b >= k; --b)
        col[b] -= col[b - 1];
  }
  for (int j = 0; j <= d; ++j)
    for (int k = 1; k <= d - j; ++k)
      for (int a = d - j; a >= k; --a)
        mono[a * w + j] -= mono[(a - 1) * w + j];
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j)
      mono[i * w + j] *= trinomial(d - i - j, i, j);
}

} // namespace

void to_monomial(const double *bernstein, int d, double *mono) {
  dispatch_degree(d, [&](auto D) { to_monomial_fixed<D.value>(bernstein, d, mono); });
}

void compose_affine(const double *mono, int d, const Mat2 &b, const Vec2 &c, double *out,
                    double *abs_out) {
  const std::size_t n = static_cast<std::size_t>(d + 1) * (d + 1);
  // Powers U^k and V^k of U = b00 s + b01 t + c0 and V = b10 s + b11 t + c1 as (s, t)
  // polynomials, and those of |U| = |b00| s + |b01| t + |c0| and |V| likewise; then
  // U^i V^j (truncated at total degree d, which it does not exceed).
  thread_local std::vector<double> pw; // [4][d+1][n]: U, V, |U|, |V| powers
  thread_local std::vector<double> prod;
  pw.assign(4 * static_cast<std::size_t>(d + 1) * n, 0.0);
  prod.resize(2 * n);
  auto power = [&](int which, int k) {
    return &pw[(which * static_cast<std::size_t>(d + 1) + k) * n];
  };
  const double lin[4][3] = {{c[0], b[0][0], b[0][1]},
                            {c[1], b[1][0], b[1][1]},
                            {std::abs(c[0]), std::abs(b[0][0]), std::abs(b[0][1])},
                            {std::abs(c[1]), std::abs(b[1][0]), std::abs(b[1][1])}};
  for (int w = 0; w < 4; ++w) {
    power(w, 0)[0] = 1;
    for (int k = 1; k <= d; ++k) {
      const double *x = power(w, k - 1);
      double *o = power(w, k);
      for (int i = 0; i < k; ++i)
        for (int j = 0; i + j < k; ++j) {
          const double v = x[static_cast<std::size_t>(i) * (d + 1) + j];
          o[static_cast<std::size_t>(i) * (d + 1) + j] += lin[w][0] * v;
          o[static_cast<std::size_t>(i + 1) * (d + 1) + j] += lin[w][1] * v;
          o[static_cast<std::size_t>(i) * (d + 1) + j + 1] += lin[w][2] * v;
        }
    }
  }
  std::fill(out, out + n, 0.0);
  std::fill(abs_out, abs_out + n, 0.0);
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j) {
      const double a = mono[static_cast<std::size_t>(i) * (d + 1) + j];
      if (a == 0)
        continue;
      for (int pass = 0; pass < 2; ++pass) {
        const double *pu = power(2 * pass, i), *pv = power(2 * pass + 1, j);
        double *o = pass == 0 ? out : abs_out;
        const double coef = pass == 0 ? a : std::abs(a);
        for (int p = 0; p <= i; ++p)
          for (int q = 0; p + q <= i; ++q) {
            const double x = coef * pu[static_cast<std::size_t>(p) * (d + 1) + q];
            if (x == 0)
              continue;
            for (int r = 0; r <= j; ++r)
              for (int t = 0; r + t <= j; ++t)
                o[static_cast<std::size_t>(p + r) * (d + 1) + q + t] +=
                    x * pv[static_cast<std::size_t>(r) * (d + 1) + t];
          }
      }
    }
}

namespace {

// Scalar (util/no_vectorize.hpp), the powers on a stack sized by the degree: vectorised, those
// stack arrays stall on store forwarding.
template <int D>
HOCT_NO_VECTORIZE double taylor_fixed(const double *mono, int d_run, double x, double y,
                                      double *e) {
  const int d = D >= 0 ? D : d_run;
  // e_ab = sum_{i>=a, j>=b} m_ij C(i,a) C(j,b) x^(i-a) y^(j-b), in two passes: along v,
  // t_ib = sum_{j>=b} m_ij C(j,b) y^(j-b) (into e), then along u, e_ab = sum_{i>=a} C(i,a)
  // x^(i-a) t_ib. Along any term's path at most 4d + 2 roundings (the two powers, four
  // products, two sums of at most d + 1 terms), so the rounding of e_ab is at most gamma_(4d+2)
  // (Higham 3.1) times the sum of the magnitudes of its terms; summed over (a, b) those are
  // sum_ij |m_ij| (1+|x|)^i (1+|y|)^j, returned scaled so that 64 eps times it covers
  // gamma_(4d+2).
  const int w = d + 1;
  constexpr int kStack = D >= 0 ? D + 1 : 64;
  double px[kStack], py[kStack];
  double *xs = px, *ys = py;
  std::vector<double> heap;
  if (w > kStack) {
    heap.resize(2 * static_cast<std::size_t>(w));
    xs = heap.data();
    ys = xs + w;
  }
  xs[0] = ys[0] = 1;
  for (int i = 1; i <= d; ++i) {
    xs[i] = xs[i - 1] * x;
    ys[i] = ys[i - 1] * y;
  }
  double magnitude = 0;
  const double ax = 1 + std::abs(x), ay = 1 + std::abs(y);
  for (int i = d; i >= 0; --i) {
    const double *row = &mono[static_cast<std::size_t>(i) * w];
    double *t = &e[static_cast<std::size_t>(i) * w];
    double r = 0;
    for (int j = d - i; j >= 0; --j)
      r = r * ay + std::abs(row[j]);
    magnitude = magnitude * ax + r;
    for (int b = 0; i + b <= d; ++b) {
      double sum = 0;
      for (int j = b; i + j <= d; ++j)
        sum += row[j] * binomial(j, b) * ys[j - b];
      t[b] = sum;
    }
  }
  for (int a = 0; a <= d; ++a)
    for (int b = 0; a + b <= d; ++b) {
      double sum = e[static_cast<std::size_t>(a) * w + b];
      for (int i = a + 1; i + b <= d; ++i)
        sum += binomial(i, a) * xs[i - a] * e[static_cast<std::size_t>(i) * w + b];
      e[static_cast<std::size_t>(a) * w + b] = sum;
    }
  return magnitude * std::max(1.0, (4.0 * d + 4) / 60);
}

} // namespace

double taylor_expansion(const double *mono, int d, double x, double y, double *e) {
  return dispatch_degree(d, [&](auto D) { return taylor_fixed<D.value>(mono, d, x, y, e); });
}

} // namespace hoct
