#include "poly/tensor_bernstein.hpp"

#include "poly/binomial.hpp"
#include "poly/lattice.hpp"
#include "poly/monomial.hpp"

#include <algorithm>
#include <stdexcept>

namespace hoct {
namespace {

// In-place de Casteljau split of a strided row of n+1 values at 1/2: left and right halves.
void split_row(const double *in, int n, int stride, double *left, double *right, int ostride) {
  double w[64] = {};
  for (int i = 0; i <= n; ++i)
    w[i] = in[i * stride];
  left[0] = w[0];
  right[n * ostride] = w[n];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i)
      w[i] = 0.5 * (w[i] + w[i + 1]);
    left[r * ostride] = w[0];
    right[(n - r) * ostride] = w[n - r];
  }
}

} // namespace

TensorBernstein::TensorBernstein(int m, int n, std::vector<double> c)
    : m_(m), n_(n), b_(std::move(c)) {
  if (m < 0 || n < 0 || m > 60 || n > 60 || static_cast<int>(b_.size()) != (m + 1) * (n + 1))
    throw std::invalid_argument("TensorBernstein: bad degree or coefficient count");
}

TensorBernstein TensorBernstein::from_triangle(const BernsteinTriangle &p) {
  const int d = p.degree();
  const std::vector<double> mono = to_monomial(p);
  // Monomials -> tensor Bernstein of bidegree (d, d): u^a = sum_{i>=a} C(i,a)/C(d,a) B_i^d(u).
  std::vector<double> t((d + 1) * (d + 1), 0.0);
  for (int i = 0; i <= d; ++i)
    for (int j = 0; j <= d; ++j) {
      double s = 0;
      for (int a = 0; a <= i; ++a)
        for (int b = 0; b <= j && a + b <= d; ++b)
          s += binomial(i, a) / binomial(d, a) * binomial(j, b) / binomial(d, b) *
               mono[a * (d + 1) + b];
      t[i * (d + 1) + j] = s;
    }
  return TensorBernstein(d, d, std::move(t));
}

double TensorBernstein::operator()(double s, double t) const {
  // de Casteljau in t for each row i, then in s.
  double row[64], col[64];
  for (int i = 0; i <= m_; ++i) {
    for (int j = 0; j <= n_; ++j)
      col[j] = b_[i * (n_ + 1) + j];
    for (int r = 1; r <= n_; ++r)
      for (int j = 0; j <= n_ - r; ++j)
        col[j] = (1 - t) * col[j] + t * col[j + 1];
    row[i] = col[0];
  }
  for (int r = 1; r <= m_; ++r)
    for (int i = 0; i <= m_ - r; ++i)
      row[i] = (1 - s) * row[i] + s * row[i + 1];
  return row[0];
}

TensorBernstein TensorBernstein::ds() const {
  if (m_ == 0)
    return TensorBernstein(0, n_, std::vector<double>(n_ + 1, 0.0));
  std::vector<double> c(m_ * (n_ + 1));
  for (int i = 0; i < m_; ++i)
    for (int j = 0; j <= n_; ++j)
      c[i * (n_ + 1) + j] = m_ * (coefficient(i + 1, j) - coefficient(i, j));
  return TensorBernstein(m_ - 1, n_, std::move(c));
}

TensorBernstein TensorBernstein::dt() const {
  if (n_ == 0)
    return TensorBernstein(m_, 0, std::vector<double>(m_ + 1, 0.0));
  std::vector<double> c((m_ + 1) * n_);
  for (int i = 0; i <= m_; ++i)
    for (int j = 0; j < n_; ++j)
      c[i * n_ + j] = n_ * (coefficient(i, j + 1) - coefficient(i, j));
  return TensorBernstein(m_, n_ - 1, std::move(c));
}

std::array<TensorBernstein, 4> TensorBernstein::quarters() const {
  const int w = n_ + 1, sz = (m_ + 1) * w;
  std::vector<double> lo_s(sz), hi_s(sz);
  for (int j = 0; j <= n_; ++j)
    split_row(&b_[j], m_, w, &lo_s[j], &hi_s[j], w);
  std::array<TensorBernstein, 4> q;
  std::vector<double> a(sz), b(sz);
  for (int half = 0; half < 2; ++half) {
    const std::vector<double> &src = half == 0 ? lo_s : hi_s;
    for (int i = 0; i <= m_; ++i)
      split_row(&src[i * w], n_, 1, &a[i * w], &b[i * w], 1);
    q[half] = TensorBernstein(m_, n_, a);
    q[2 + half] = TensorBernstein(m_, n_, b);
  }
  return q;
}

std::pair<double, double> TensorBernstein::bounds() const {
  auto [lo, hi] = std::minmax_element(b_.begin(), b_.end());
  return {*lo, *hi};
}

bool TensorBernstein::excludes_zero() const {
  auto [lo, hi] = bounds();
  return lo > 0 || hi < 0;
}

} // namespace hoct
