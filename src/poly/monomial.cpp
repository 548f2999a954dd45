#include "poly/monomial.hpp"

#include "poly/binomial.hpp"
#include "poly/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {

std::vector<double> to_monomial(const BernsteinTriangle &p) {
  std::vector<double> mono((p.degree() + 1) * (p.degree() + 1));
  to_monomial(p.coefficients().data(), p.degree(), mono.data());
  return mono;
}

void to_monomial(const double *bernstein, int d, double *mono) {
  std::fill(mono, mono + (d + 1) * (d + 1), 0.0);
  for (int b = 0; b <= d; ++b)
    for (int a = 0; a + b <= d; ++a) {
      const int k = d - a - b;
      const double c = bernstein[lattice_index(d, a, b)] * trinomial(k, a, b);
      // (1-u-v)^k = sum_{x+y<=k} k!/(x! y! (k-x-y)!) (-1)^(x+y) u^x v^y
      for (int y = 0; y <= k; ++y)
        for (int x = 0; x + y <= k; ++x) {
          const double w = trinomial(k - x - y, x, y) * (((x + y) & 1) ? -1.0 : 1.0);
          mono[(a + x) * (d + 1) + (b + y)] += c * w;
        }
    }
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

double taylor_expansion(const double *mono, int d, double x, double y, double *e) {
  // e_ab = sum_{i>=a, j>=b} m_ij C(i,a) C(j,b) x^(i-a) y^(j-b).
  thread_local std::vector<double> powers;
  powers.resize(2 * static_cast<std::size_t>(d + 1));
  double *px = powers.data(), *py = px + d + 1;
  px[0] = py[0] = 1;
  for (int i = 1; i <= d; ++i) {
    px[i] = px[i - 1] * x;
    py[i] = py[i - 1] * y;
  }
  double magnitude = 0;
  for (int a = 0; a <= d; ++a)
    for (int b = 0; a + b <= d; ++b) {
      double sum = 0;
      for (int i = a; i <= d; ++i) {
        const double ci = binomial(i, a) * px[i - a];
        const double *row = &mono[static_cast<std::size_t>(i) * (d + 1)];
        for (int j = b; i + j <= d; ++j) {
          const double term = row[j] * ci * binomial(j, b) * py[j - b];
          sum += term;
          magnitude += std::abs(term);
        }
      }
      e[static_cast<std::size_t>(a) * (d + 1) + b] = sum;
    }
  return magnitude;
}

} // namespace hoct
