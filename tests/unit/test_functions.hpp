// Analytic functions with known critical points, shared by the tests.
#pragma once

#include "mesh/mesh_input.hpp"

#include <cmath>
#include <cstring>
#include <vector>

namespace hoct::testing {

// A rotation of R^3 by Euler angles (defaults chosen so that no mesh vertex of the test meshes
// lies on the zero circles of x'y'z').
struct Rotation {
  double r[3][3];
  explicit Rotation(double a = 0.3, double b = 0.7, double c = 1.1) {
    const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b),
                 cc = std::cos(c), sc = std::sin(c);
    const double m[3][3] = {{ca * cc - sa * cb * sc, -ca * sc - sa * cb * cc, sa * sb},
                            {sa * cc + ca * cb * sc, -sa * sc + ca * cb * cc, -ca * sb},
                            {sb * sc, sb * cc, cb}};
    std::memcpy(r, m, sizeof(r));
  }
  Vec3 apply(const Vec3 &p) const {
    return {r[0][0] * p[0] + r[0][1] * p[1] + r[0][2] * p[2],
            r[1][0] * p[0] + r[1][1] * p[1] + r[1][2] * p[2],
            r[2][0] * p[0] + r[2][1] * p[1] + r[2][2] * p[2]};
  }
  Vec3 inverse(const Vec3 &q) const {
    return {r[0][0] * q[0] + r[1][0] * q[1] + r[2][0] * q[2],
            r[0][1] * q[0] + r[1][1] * q[1] + r[2][1] * q[2],
            r[0][2] * q[0] + r[1][2] * q[1] + r[2][2] * q[2]};
  }
};

// Monomial coefficients (ascending powers) of scale * integral_0^x prod (t - r_i) dt: a
// univariate polynomial whose critical points are exactly the r_i.
inline std::vector<double> antiderivative_of_roots(const std::vector<double> &r,
                                                   double scale = 1.0) {
  std::vector<double> p = {scale};
  for (double root : r) {
    std::vector<double> q(p.size() + 1, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      q[i] -= root * p[i];
      q[i + 1] += p[i];
    }
    p = q;
  }
  std::vector<double> a(p.size() + 1, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    a[i + 1] = p[i] / static_cast<double>(i + 1);
  return a;
}

inline double horner(const std::vector<double> &a, double x) {
  double s = 0;
  for (auto it = a.rbegin(); it != a.rend(); ++it)
    s = s * x + *it;
  return s;
}

} // namespace hoct::testing
