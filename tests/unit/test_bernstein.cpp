// Bernstein forms against direct evaluation of polynomials given in monomial form.
#include "poly/bernstein_triangle.hpp"
#include "poly/bernstein_univariate.hpp"
#include "poly/lagrange_node_order.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"
#include "poly/sample_fit.hpp"

#include "util/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

namespace hoct {
namespace {

// A random polynomial of total degree d in monomial form, with its exact derivatives.
struct Monomial {
  int d;
  std::vector<double> a; // a[i*(d+1)+j] for u^i v^j, i + j <= d
  Monomial(int degree, std::mt19937_64 &rng) : d(degree), a((d + 1) * (d + 1), 0.0) {
    std::uniform_real_distribution<double> U(-1, 1);
    for (int i = 0; i <= d; ++i)
      for (int j = 0; i + j <= d; ++j)
        a[i * (d + 1) + j] = U(rng);
  }
  double eval(double u, double v, int du = 0, int dv = 0) const {
    double s = 0;
    for (int i = du; i <= d; ++i)
      for (int j = dv; i + j <= d; ++j) {
        double c = a[i * (d + 1) + j];
        for (int k = 0; k < du; ++k)
          c *= (i - k);
        for (int k = 0; k < dv; ++k)
          c *= (j - k);
        s += c * std::pow(u, i - du) * std::pow(v, j - dv);
      }
    return s;
  }
};

class BernsteinDegree : public ::testing::TestWithParam<int> {};

TEST_P(BernsteinDegree, LagrangeToBernsteinMatchesDirectEvaluationInBothNodeOrders) {
  const int d = GetParam();
  std::mt19937_64 rng(1234 + d);
  std::uniform_real_distribution<double> U(0, 1);
  for (NodeOrdering ord : {NodeOrdering::Vtk, NodeOrdering::Gmsh}) {
    for (int trial = 0; trial < 5; ++trial) {
      Monomial m(d, rng);
      const auto &perm = node_order_to_lattice(ord, d);
      // Node values as a file would list them, then permuted to lattice order.
      std::vector<double> file_values(perm.size()), lattice_values(perm.size());
      for (std::size_t i = 0; i < perm.size(); ++i) {
        const auto p = lattice_point(d, perm[i]);
        file_values[i] = m.eval(static_cast<double>(p[0]) / d, static_cast<double>(p[1]) / d);
      }
      for (std::size_t i = 0; i < perm.size(); ++i)
        lattice_values[perm[i]] = file_values[i];
      const BernsteinTriangle b = bernstein_from_lattice_values(lattice_values.data(), d);
      for (int k = 0; k < 50; ++k) {
        double u = U(rng), v = U(rng);
        if (u + v > 1) {
          u = 1 - u;
          v = 1 - v;
        }
        EXPECT_NEAR(b(u, v), m.eval(u, v), 1e-11) << "d=" << d;
        const auto g = b.gradient(u, v);
        EXPECT_NEAR(g[0], m.eval(u, v, 1, 0), 1e-9);
        EXPECT_NEAR(g[1], m.eval(u, v, 0, 1), 1e-9);
        const auto h = b.hessian(u, v);
        EXPECT_NEAR(h[0][0], m.eval(u, v, 2, 0), 1e-7);
        EXPECT_NEAR(h[0][1], m.eval(u, v, 1, 1), 1e-7);
        EXPECT_NEAR(h[1][0], m.eval(u, v, 1, 1), 1e-7);
        EXPECT_NEAR(h[1][1], m.eval(u, v, 0, 2), 1e-7);
      }
    }
  }
}

TEST(LagrangeToBernstein, SameBitsAsOneDotProductPerCoefficient) {
  // The conversion computes its dot products four rows at a time; each must still be the plain
  // j-ordered sum, bit for bit (the trees do not depend on how the conversion is scheduled).
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(-1e3, 1e3);
  for (int d = 1; d <= kMaxDegree; ++d) {
    const int n = lattice_size(d);
    const std::vector<double> &m = lagrange_to_bernstein_triangle(d);
    std::vector<double> values(n), got(n);
    for (double &x : values)
      x = U(rng);
    bernstein_from_lattice_values(values.data(), d, got.data());
    for (int i = 0; i < n; ++i) {
      double s = 0.0;
      for (int j = 0; j < n; ++j)
        s += m[static_cast<std::size_t>(i) * n + j] * values[j];
      ASSERT_EQ(std::memcmp(&s, &got[i], sizeof s), 0) << "degree " << d << " coefficient " << i;
    }
  }
}

TEST_P(BernsteinDegree, JetGivesValueGradientAndHessian) {
  // Against the closed-form derivatives of the monomial the polynomial interpolates, inside,
  // on the boundary and outside the triangle.
  const int d = GetParam();
  std::mt19937_64 rng(7 + d);
  Monomial m(d, rng);
  std::vector<double> vals(lattice_size(d));
  for (int i = 0; i < lattice_size(d); ++i) {
    const auto p = lattice_point(d, i);
    vals[i] = d == 0 ? m.eval(0, 0)
                     : m.eval(static_cast<double>(p[0]) / d, static_cast<double>(p[1]) / d);
  }
  const BernsteinTriangle b = bernstein_from_lattice_values(vals.data(), d);
  for (const Vec2 &p :
       {Vec2{0.2, 0.3}, Vec2{0, 0}, Vec2{1, 0}, Vec2{0.5, 0.5}, Vec2{0.05, 0.9}, Vec2{-0.2, 0.7}}) {
    const BernsteinTriangle::Jet j = b.jet(p[0], p[1]);
    const double tol = 1e-9 * (1 + d * d * d);
    EXPECT_NEAR(j.value, m.eval(p[0], p[1]), tol);
    EXPECT_NEAR(j.gradient[0], m.eval(p[0], p[1], 1, 0), tol);
    EXPECT_NEAR(j.gradient[1], m.eval(p[0], p[1], 0, 1), tol);
    EXPECT_NEAR(j.hessian[0][0], m.eval(p[0], p[1], 2, 0), tol);
    EXPECT_NEAR(j.hessian[0][1], m.eval(p[0], p[1], 1, 1), tol);
    EXPECT_NEAR(j.hessian[1][0], m.eval(p[0], p[1], 1, 1), tol);
    EXPECT_NEAR(j.hessian[1][1], m.eval(p[0], p[1], 0, 2), tol);
  }
}

TEST_P(BernsteinDegree, EdgeAndSegmentRestrictions) {
  const int d = GetParam();
  std::mt19937_64 rng(99 + d);
  std::uniform_real_distribution<double> U(-0.5, 1.5);
  Monomial m(d, rng);
  std::vector<double> vals(lattice_size(d));
  for (int i = 0; i < lattice_size(d); ++i) {
    const auto p = lattice_point(d, i);
    vals[i] = m.eval(static_cast<double>(p[0]) / d, static_cast<double>(p[1]) / d);
  }
  const BernsteinTriangle b = bernstein_from_lattice_values(vals.data(), d);
  const Vec2 corner[3] = {{0, 0}, {1, 0}, {0, 1}};
  for (int k = 0; k < 3; ++k) {
    const BernsteinPoly e = b.edge(k);
    ASSERT_EQ(e.degree(), d);
    for (double t : {0.0, 0.1, 0.37, 0.5, 0.93, 1.0}) {
      const Vec2 &p = corner[k], &q = corner[(k + 1) % 3];
      EXPECT_NEAR(e(t), m.eval(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])), 1e-11);
    }
  }
  for (int trial = 0; trial < 20; ++trial) {
    const Vec2 p = {U(rng), U(rng)}, q = {U(rng), U(rng)};
    const BernsteinPoly s = b.restrict_to_segment(p, q);
    // Points outside the triangle extrapolate: compare relative to the magnitude.
    for (double t : {0.0, 0.25, 0.6, 1.0}) {
      const double exact = m.eval(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]));
      EXPECT_NEAR(s(t), exact, 1e-10 * std::max(1.0, std::abs(exact)));
    }
    // The coefficient hull encloses the values on the segment.
    auto [lo, hi] = s.bounds();
    for (int i = 0; i <= 40; ++i) {
      const double v = s(i / 40.0);
      EXPECT_LE(lo, v + 1e-12);
      EXPECT_GE(hi, v - 1e-12);
    }
  }
}

TEST_P(BernsteinDegree, ElevationProductAndUnivariateOperations) {
  const int d = GetParam();
  std::mt19937_64 rng(7 + d);
  Monomial m1(d, rng), m2(2, rng);
  auto to_bern = [](const Monomial &m) {
    std::vector<double> vals(lattice_size(m.d));
    for (int i = 0; i < lattice_size(m.d); ++i) {
      const auto p = lattice_point(m.d, i);
      vals[i] = m.eval(static_cast<double>(p[0]) / m.d, static_cast<double>(p[1]) / m.d);
    }
    return bernstein_from_lattice_values(vals.data(), m.d);
  };
  const BernsteinTriangle b1 = to_bern(m1), b2 = to_bern(m2);
  const BernsteinTriangle e = b1.elevated(d + 3), prod = b1 * b2;
  EXPECT_EQ(e.degree(), d + 3);
  EXPECT_EQ(prod.degree(), d + 2);
  for (double u : {0.0, 0.2, 0.5})
    for (double v : {0.0, 0.3, 0.5}) {
      EXPECT_NEAR(e(u, v), m1.eval(u, v), 1e-11);
      EXPECT_NEAR(prod(u, v), m1.eval(u, v) * m2.eval(u, v), 1e-10);
    }
  const BernsteinPoly p = b1.edge(0);
  const BernsteinPoly dp = p.derivative(), r = p.reversed(), pe = p.elevated(d + 2);
  const auto [left, right] = p.split(0.3);
  const BernsteinPoly sub = p.subinterval(0.2, 0.7);
  for (double t : {0.0, 0.15, 0.5, 0.8, 1.0}) {
    EXPECT_NEAR(dp(t), m1.eval(t, 0, 1, 0), 1e-9);
    EXPECT_NEAR(r(t), p(1 - t), 1e-12);
    EXPECT_NEAR(pe(t), p(t), 1e-12);
    EXPECT_NEAR(left(t), p(0.3 * t), 1e-12);
    EXPECT_NEAR(right(t), p(0.3 + 0.7 * t), 1e-12);
    EXPECT_NEAR(sub(t), p(0.2 + 0.5 * t), 1e-12);
  }
}

TEST_P(BernsteinDegree, ArbitrarySamplesRecoverThePolynomial) {
  const int d = GetParam();
  std::mt19937_64 rng(555 + d);
  std::uniform_real_distribution<double> U(0, 1);
  Monomial m(d, rng);
  std::vector<Vec2> pos;
  std::vector<double> vals;
  // Perturbed lattice positions: a well-posed but irregular sample set.
  for (int i = 0; i < lattice_size(d); ++i) {
    const auto p = lattice_point(d, i);
    double u = (p[0] + 0.3 * (U(rng) - 0.5)) / (d + 0.5) + 0.02;
    double v = (p[1] + 0.3 * (U(rng) - 0.5)) / (d + 0.5) + 0.02;
    pos.push_back({u, v});
    vals.push_back(m.eval(u, v));
  }
  const BernsteinTriangle b = bernstein_from_samples(pos, vals, d);
  for (int k = 0; k < 20; ++k) {
    const double u = U(rng) * 0.5, v = U(rng) * 0.5;
    EXPECT_NEAR(b(u, v), m.eval(u, v), 1e-7);
  }
}

INSTANTIATE_TEST_SUITE_P(Degrees1To8, BernsteinDegree, ::testing::Range(1, 9));

TEST(BernsteinTriangle, GeneralDegreesAgreeWithEvaluation) {
  // Degrees 1 to 8 take unrolled fixed-degree paths for the jet and the segment restriction
  // (tested above against analytic values); 9 and more the general ones: against evaluation of
  // the same Bernstein polynomial (random coefficients, points inside the triangle, where both
  // round at the level of the coefficients).
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> U(-1, 1), W(0, 1);
  auto inside = [&] {
    double u = W(rng), v = W(rng);
    if (u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    return Vec2{u, v};
  };
  for (int d : {7, 8, 9, 10, 12}) {
    std::vector<double> c(lattice_size(d));
    for (double &x : c)
      x = U(rng);
    const BernsteinTriangle b(d, c);
    const BernsteinTriangle bu = b.du(), bv = b.dv();
    const double tol = 1e-13 * d * d;
    for (int trial = 0; trial < 20; ++trial) {
      const Vec2 p = inside(), q = inside();
      const BernsteinPoly s = b.restrict_to_segment(p, q);
      ASSERT_EQ(s.degree(), d);
      for (double t : {0.0, 0.3, 0.71, 1.0})
        EXPECT_NEAR(s(t), b(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])), tol)
            << "degree " << d;
      const BernsteinTriangle::Jet j = b.jet(p[0], p[1]);
      EXPECT_NEAR(j.value, b(p[0], p[1]), tol) << "degree " << d;
      EXPECT_NEAR(j.gradient[0], bu(p[0], p[1]), tol * d) << "degree " << d;
      EXPECT_NEAR(j.gradient[1], bv(p[0], p[1]), tol * d) << "degree " << d;
      EXPECT_NEAR(j.hessian[0][1], bu.dv()(p[0], p[1]), tol * d * d) << "degree " << d;
    }
  }
}

TEST(SampleFit, RejectsIllConditionedAndInsufficientSamples) {
  // All samples on one line: no quadratic is determined.
  std::vector<Vec2> pos;
  std::vector<double> vals;
  for (int i = 0; i < 6; ++i) {
    pos.push_back({i / 6.0, 0.0});
    vals.push_back(i);
  }
  try {
    bernstein_from_samples(pos, vals, 2);
    FAIL() << "collinear samples accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("condition number"), std::string::npos) << e.what();
  }
  pos.resize(5);
  vals.resize(5);
  EXPECT_THROW(bernstein_from_samples(pos, vals, 2), Error);
  // Six samples on a conic (a circle) cannot determine a quadratic either.
  pos.clear();
  vals.clear();
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * M_PI * i / 6;
    pos.push_back({0.3 + 0.2 * std::cos(a), 0.3 + 0.2 * std::sin(a)});
    vals.push_back(std::cos(a));
  }
  EXPECT_THROW(bernstein_from_samples(pos, vals, 2), Error);
  // More samples than coefficients that do not come from a quadratic.
  pos.clear();
  vals.clear();
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; i + j <= 4; ++j) {
      pos.push_back({i / 4.0, j / 4.0});
      vals.push_back(std::pow(i / 4.0, 4));
    }
  try {
    bernstein_from_samples(pos, vals, 2);
    FAIL() << "non-quadratic samples accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("residual"), std::string::npos) << e.what();
  }
}

TEST(NodeOrder, MatchesTheOrderVtkAndGmshUse) {
  // Parametric lattice points (a, b) of VTK_LAGRANGE_TRIANGLE and Gmsh's complete triangles,
  // as printed by vtkLagrangeTriangle::GetParametricCoords and gmsh getElementProperties.
  const std::vector<std::array<int, 2>> deg4 = {{0, 0}, {4, 0}, {0, 4}, {1, 0}, {2, 0},
                                                {3, 0}, {3, 1}, {2, 2}, {1, 3}, {0, 3},
                                                {0, 2}, {0, 1}, {1, 1}, {2, 1}, {1, 2}};
  const std::vector<std::array<int, 2>> deg5_interior = {{1, 1}, {3, 1}, {1, 3},
                                                         {2, 1}, {2, 2}, {1, 2}};
  for (NodeOrdering ord : {NodeOrdering::Vtk, NodeOrdering::Gmsh}) {
    const auto &p4 = node_order_to_lattice(ord, 4);
    ASSERT_EQ(p4.size(), deg4.size());
    for (std::size_t i = 0; i < deg4.size(); ++i)
      EXPECT_EQ(p4[i], lattice_index(4, deg4[i][0], deg4[i][1])) << i;
    const auto &p5 = node_order_to_lattice(ord, 5);
    for (std::size_t i = 0; i < deg5_interior.size(); ++i)
      EXPECT_EQ(p5[15 + i], lattice_index(5, deg5_interior[i][0], deg5_interior[i][1])) << i;
  }
  EXPECT_EQ(degree_from_node_count(10), 3);
  EXPECT_EQ(degree_from_node_count(7), -1);
}

} // namespace
} // namespace hoct
