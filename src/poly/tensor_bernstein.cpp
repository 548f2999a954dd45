#include "poly/tensor_bernstein.hpp"

#include "poly/binomial.hpp"
#include "poly/degree_dispatch.hpp"
#include "poly/lattice.hpp"
#include "poly/monomial.hpp"
#include "util/no_vectorize.hpp"

#include <algorithm>
#include <stdexcept>

namespace hoct {
namespace {

// In-place de Casteljau split of a strided row of n+1 values at 1/2: left and right halves.
void split_row(const double *in, int n, int stride, double *left, double *right, int ostride) {
  if (n <= 0 || n >= 64) { // degree 0 (the constructor bounds degrees by 60)
    left[0] = right[0] = in[0];
    return;
  }
  double w[64];
  for (int i = 0; i <= n; ++i)
    w[i] = in[i * stride];
  left[0] = in[0];
  right[n * ostride] = in[n * stride]; // read before any write to in but left[0] = in[0]
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

namespace {

template <int D> void from_monomial_fixed(const double *mono, int d_run, double *out) {
  // u^a = sum_{i>=a} C(i,a)/C(d,a) B_i^d(u), likewise in v: out = W mono W^T with
  // W[i][a] = C(i,a)/C(d,a) (a <= i), in two passes (along v into `out`, then along u in place,
  // each row i from the rows a <= i not yet overwritten: i descending).
  const int d = D >= 0 ? D : d_run;
  const int w = d + 1;
  constexpr int kStack = D >= 0 ? (D + 1) * (D + 1) : 16 * 16;
  double weights[kStack];
  std::vector<double> heap;
  double *W = weights;
  if (w * w > kStack) {
    heap.resize(static_cast<std::size_t>(w) * w);
    W = heap.data();
  }
  for (int i = 0; i <= d; ++i)
    for (int a = 0; a <= i; ++a)
      W[i * w + a] = binomial(i, a) / binomial(d, a);
  for (int a = 0; a <= d; ++a)
    for (int j = 0; j <= d; ++j) {
      double s = 0;
      for (int b = 0; b <= j && a + b <= d; ++b)
        s += W[j * w + b] * mono[a * w + b];
      out[a * w + j] = s;
    }
  for (int i = d; i >= 0; --i)
    for (int j = 0; j <= d; ++j) {
      double s = 0;
      for (int a = 0; a <= i; ++a)
        s += W[i * w + a] * out[a * w + j];
      out[i * w + j] = s;
    }
}

} // namespace

void TensorBernstein::from_monomial(const double *mono, int d, double *out) {
  dispatch_degree(d, [&](auto D) { from_monomial_fixed<D.value>(mono, d, out); });
}

TensorBernstein TensorBernstein::from_triangle(const BernsteinTriangle &p) {
  const int d = p.degree();
  const std::vector<double> mono = to_monomial(p);
  std::vector<double> t((d + 1) * (d + 1), 0.0);
  from_monomial(mono.data(), d, t.data());
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

namespace {

// split_row for a compile-time degree N (unrolled; the subdivision's inner loop).
template <int N>
inline void split_row_fixed(const double *in, int stride, double *left, double *right,
                            int ostride) {
  double w[N + 1];
#pragma GCC unroll 16
  for (int i = 0; i <= N; ++i)
    w[i] = in[i * stride];
  left[0] = w[0];
  right[N * ostride] = w[N];
#pragma GCC unroll 16
  for (int r = 1; r <= N; ++r) {
#pragma GCC unroll 16
    for (int i = 0; i <= N - r; ++i)
      w[i] = 0.5 * (w[i] + w[i + 1]);
    left[r * ostride] = w[0];
    right[(N - r) * ostride] = w[N - r];
  }
}

// Scalar (util/no_vectorize.hpp): vectorised, its stack arrays stall on store forwarding.
template <int M> HOCT_NO_VECTORIZE void split_quarters_fixed(const double *b, double *const q[4]) {
  constexpr int w = M + 1;
#pragma GCC unroll 16
  for (int j = 0; j <= M; ++j)
    split_row_fixed<M>(&b[j], w, &q[0][j], &q[1][j], w);
  for (int half = 0; half < 2; ++half)
#pragma GCC unroll 16
    for (int i = 0; i <= M; ++i)
      split_row_fixed<M>(&q[half][i * w], 1, &q[half][i * w], &q[2 + half][i * w], 1);
}

} // namespace

void TensorBernstein::split_quarters(const double *b, int m, int n, double *const q[4]) {
  // Equal small degrees (the gradient of cells up to degree 9): unrolled versions.
  if (m == n && dispatch_degree(m, [&](auto D) {
        if constexpr (D.value >= 1) {
          split_quarters_fixed<D.value>(b, q);
          return true;
        }
        return false;
      }))
    return;
  // Split along s into q[0] (s low) and q[1] (s high), then each along t in place into
  // (q[0], q[2]) and (q[1], q[3]).
  const int w = n + 1;
  for (int j = 0; j <= n; ++j)
    split_row(&b[j], m, w, &q[0][j], &q[1][j], w);
  for (int half = 0; half < 2; ++half)
    for (int i = 0; i <= m; ++i)
      split_row(&q[half][i * w], n, 1, &q[half][i * w], &q[2 + half][i * w], 1);
}

void TensorBernstein::split_halves(const double *b, int m, int n, bool along_s,
                                   double *const h[2]) {
  const int w = n + 1;
  if (along_s)
    for (int j = 0; j <= n; ++j)
      split_row(&b[j], m, w, &h[0][j], &h[1][j], w);
  else
    for (int i = 0; i <= m; ++i)
      split_row(&b[i * w], n, 1, &h[0][i * w], &h[1][i * w], 1);
}

std::array<TensorBernstein, 4> TensorBernstein::quarters() const {
  const std::size_t sz = b_.size();
  std::array<std::vector<double>, 4> c;
  for (auto &v : c)
    v.resize(sz);
  double *const out[4] = {c[0].data(), c[1].data(), c[2].data(), c[3].data()};
  split_quarters(b_.data(), m_, n_, out);
  std::array<TensorBernstein, 4> q;
  for (int k = 0; k < 4; ++k)
    q[k] = TensorBernstein(m_, n_, std::move(c[k]));
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
