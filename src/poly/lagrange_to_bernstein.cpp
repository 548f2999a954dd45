#include "poly/lagrange_to_bernstein.hpp"

#include "poly/binomial.hpp"
#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <mutex>

namespace hoct {
namespace {

using MatrixLd = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

long double ipow(long double x, int k) {
  long double r = 1.0L;
  for (int i = 0; i < k; ++i)
    r *= x;
  return r;
}

std::vector<double> to_row_major(const MatrixLd &m) {
  std::vector<double> out(static_cast<std::size_t>(m.rows() * m.cols()));
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      out[static_cast<std::size_t>(i * m.cols() + j)] = static_cast<double>(m(i, j));
  return out;
}

std::vector<double> build_triangle(int d) {
  const int n = lattice_size(d);
  MatrixLd v(n, n); // v(i, j) = B_j(node_i)
  for (int i = 0; i < n; ++i) {
    const auto p = lattice_point(d, i);
    const long double u = static_cast<long double>(p[0]) / d;
    const long double w = static_cast<long double>(p[1]) / d;
    const long double l0 = 1.0L - u - w;
    for (int j = 0; j < n; ++j) {
      const auto q = lattice_point(d, j);
      const int a = q[0], b = q[1], k = d - a - b;
      v(i, j) =
          static_cast<long double>(trinomial(k, a, b)) * ipow(l0, k) * ipow(u, a) * ipow(w, b);
    }
  }
  return to_row_major(v.fullPivLu().inverse());
}

std::vector<double> build_1d(int d) {
  const int n = d + 1;
  MatrixLd v(n, n);
  for (int i = 0; i < n; ++i) {
    const long double t = static_cast<long double>(i) / d;
    for (int j = 0; j < n; ++j)
      v(i, j) = static_cast<long double>(binomial(d, j)) * ipow(t, j) * ipow(1.0L - t, d - j);
  }
  return to_row_major(v.fullPivLu().inverse());
}

void check_degree(int degree) {
  if (degree < 1 || degree > kMaxDegree)
    throw Error("polynomial degree " + std::to_string(degree) + " is not supported (1.." +
                std::to_string(kMaxDegree) + ")");
}

} // namespace

const std::vector<double> &lagrange_to_bernstein_triangle(int degree) {
  check_degree(degree);
  // Built once per degree (std::call_once: no lock on later calls from many threads).
  static std::array<std::once_flag, kMaxDegree + 1> once;
  static std::array<std::vector<double>, kMaxDegree + 1> cache;
  std::call_once(once[degree], [&] { cache[degree] = build_triangle(degree); });
  return cache[degree];
}

double lagrange_to_bernstein_norm(int degree) {
  const std::vector<double> &m = lagrange_to_bernstein_triangle(degree);
  const std::size_t n = static_cast<std::size_t>(lattice_size(degree));
  double norm = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double row = 0;
    for (std::size_t j = 0; j < n; ++j)
      row += std::abs(m[i * n + j]);
    norm = std::max(norm, row);
  }
  return norm;
}

const std::vector<double> &lagrange_to_bernstein_1d(int degree) {
  check_degree(degree);
  // Built once per degree (std::call_once: no lock on later calls from many threads).
  static std::array<std::once_flag, kMaxDegree + 1> once;
  static std::array<std::vector<double>, kMaxDegree + 1> cache;
  std::call_once(once[degree], [&] { cache[degree] = build_1d(degree); });
  return cache[degree];
}

} // namespace hoct
