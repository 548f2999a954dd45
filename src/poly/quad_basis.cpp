#include "poly/quad_basis.hpp"

#include "poly/binomial.hpp"
#include "util/error.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <mutex>
#include <string>

namespace hoct {
namespace {

void check_quad_degree(int p, int lowest) {
  if (p < lowest || p > kMaxQuadDegree)
    throw Error("quadrilateral bidegree " + std::to_string(p) + " is not supported (" +
                std::to_string(lowest) + ".." + std::to_string(kMaxQuadDegree) + ")");
}

long double lagrange_basis(int p, int i, long double x) {
  long double r = 1.0L;
  for (int m = 0; m <= p; ++m)
    if (m != i)
      r *= (x * p - m) / static_cast<long double>(i - m);
  return r;
}

long double ipow(long double x, int k) {
  long double r = 1.0L;
  for (int i = 0; i < k; ++i)
    r *= x;
  return r;
}

std::vector<double> half_steps(int p, bool bernstein) {
  std::vector<double> e(static_cast<std::size_t>((2 * p + 1) * (p + 1)));
  for (int k = 0; k <= 2 * p; ++k)
    for (int i = 0; i <= p; ++i) {
      const long double x = static_cast<long double>(k) / (2 * p);
      double v;
      if (bernstein)
        v = static_cast<double>(static_cast<long double>(binomial(p, i)) * ipow(x, i) *
                                ipow(1.0L - x, p - i));
      else if (k % 2 == 0)
        v = k / 2 == i ? 1.0 : 0.0; // exactly the node
      else
        v = static_cast<double>(lagrange_basis(p, i, x));
      e[static_cast<std::size_t>(k * (p + 1) + i)] = v;
    }
  return e;
}

std::vector<double> build_serendipity(int p) {
  const std::vector<int> boundary = quad_boundary_indices(p);
  const int nb = static_cast<int>(boundary.size());
  std::vector<std::array<int, 2>> monomials;
  for (int j = 0; j <= p; ++j)
    for (int i = 0; i <= p; ++i)
      if (std::min(i, j) <= 1)
        monomials.push_back({i, j});
  using MatrixLd = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  MatrixLd v(nb, nb); // v(node, monomial)
  auto monomial = [&](int node, const std::array<int, 2> &m) {
    const long double s = static_cast<long double>(node % (p + 1)) / p;
    const long double t = static_cast<long double>(node / (p + 1)) / p;
    return ipow(s, m[0]) * ipow(t, m[1]);
  };
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c)
      v(r, c) =
          monomial(boundary[static_cast<std::size_t>(r)], monomials[static_cast<std::size_t>(c)]);
  const MatrixLd coef = v.fullPivLu().inverse(); // monomial coefficients from boundary values
  const int ni = (p - 1) * (p - 1);
  MatrixLd at(ni, nb);
  int r = 0;
  for (int j = 1; j < p; ++j)
    for (int i = 1; i < p; ++i, ++r)
      for (int c = 0; c < nb; ++c)
        at(r, c) = monomial(i + (p + 1) * j, monomials[static_cast<std::size_t>(c)]);
  const MatrixLd s = at * coef;
  std::vector<double> out(static_cast<std::size_t>(ni * nb));
  for (int a = 0; a < ni; ++a)
    for (int b = 0; b < nb; ++b)
      out[static_cast<std::size_t>(a * nb + b)] = static_cast<double>(s(a, b));
  return out;
}

template <class Build>
const std::vector<double> &cached(std::array<std::once_flag, kMaxQuadDegree + 1> &once,
                                  std::array<std::vector<double>, kMaxQuadDegree + 1> &cache, int p,
                                  Build build) {
  std::call_once(once[static_cast<std::size_t>(p)],
                 [&] { cache[static_cast<std::size_t>(p)] = build(p); });
  return cache[static_cast<std::size_t>(p)];
}

} // namespace

const std::vector<double> &lagrange_at_half_steps(int p) {
  check_quad_degree(p, 1);
  static std::array<std::once_flag, kMaxQuadDegree + 1> once;
  static std::array<std::vector<double>, kMaxQuadDegree + 1> cache;
  return cached(once, cache, p, [](int q) { return half_steps(q, false); });
}

const std::vector<double> &bernstein_at_half_steps(int p) {
  check_quad_degree(p, 1);
  static std::array<std::once_flag, kMaxQuadDegree + 1> once;
  static std::array<std::vector<double>, kMaxQuadDegree + 1> cache;
  return cached(once, cache, p, [](int q) { return half_steps(q, true); });
}

const std::vector<double> &serendipity_interior(int p) {
  check_quad_degree(p, 2);
  static std::array<std::once_flag, kMaxQuadDegree + 1> once;
  static std::array<std::vector<double>, kMaxQuadDegree + 1> cache;
  return cached(once, cache, p, build_serendipity);
}

std::vector<int> quad_boundary_indices(int p) {
  std::vector<int> out;
  for (int j = 0; j <= p; ++j)
    for (int i = 0; i <= p; ++i)
      if (i == 0 || j == 0 || i == p || j == p)
        out.push_back(i + (p + 1) * j);
  return out;
}

} // namespace hoct
