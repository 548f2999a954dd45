// `two-triangle`: the thesis' toy (section 5.4), two degree-5 cells sharing an edge with many
// interior critical points. The unit square is split on its diagonal (0,0)-(1,1): cell 0 is
// (0,0),(1,0),(1,1) (below the diagonal, y < x), cell 1 is (0,0),(1,1),(0,1). The field is one
// global quintic
//
//   f(x, y) = 40 A(x) + 40 s B(y) + c x y,
//   A(x) = integral_0^x (t - .35)(t - .60)(t - .75)(t - .92) dt,
//   B(y) = integral_0^y (t - .10)(t - .30)(t - .65)(t - .85) dt,
//
// with s in [0.8, 1.2] and the coupling c in [-0.003, 0.003] drawn from the seed. Without coupling
// the 16 critical points are exactly the grid (r_i, s_j) of the roots above: 11 below the diagonal
// (in cell 0), 5 above (in cell 1), none within 0.035 of it; minima where A'' > 0 and B'' > 0,
// maxima where both are negative, saddles elsewhere (4 minima, 4 maxima, 8 saddles). The coupling
// moves each by less than 0.008 (|c y| <= 0.003 against |40 A''| >= 0.40 and |40 s B''| >= 1.2 at
// the roots), so the counts stay 11 and 5, and the critical points stay non-degenerate.
// With --degree >= 5 the cells represent f exactly; lower degrees interpolate it.
#include "datasets/dataset_options.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/seeded_random.hpp"
#include "util/error.hpp"

#include <array>

namespace hoct {
namespace {

// Monomial coefficients (degree 0..5) of integral_0^x prod_i (t - r_i) dt.
std::array<double, 6> quintic_antiderivative(const std::array<double, 4> &roots) {
  std::array<double, 5> p = {1, 0, 0, 0, 0}; // prod (t - r_i), degree 0..4
  int degree = 0;
  for (double r : roots) {
    for (int i = degree + 1; i >= 1; --i)
      p[i] = p[i - 1] - r * p[i];
    p[0] = -r * p[0];
    ++degree;
  }
  std::array<double, 6> q{};
  for (int i = 0; i < 5; ++i)
    q[i + 1] = p[i] / (i + 1);
  return q;
}

double horner(const std::array<double, 6> &q, double x) {
  double s = 0;
  for (int i = 5; i >= 0; --i)
    s = s * x + q[i];
  return s;
}

} // namespace

MeshInput generate_two_triangle(const DatasetOptions &o) {
  if (o.cells != 0 && o.cells != 2)
    throw Error("two-triangle: the dataset has exactly 2 cells; --cells does not apply");
  const int d = dataset_degree(o, 5, "two-triangle");
  SeededRandom rng(o.seed, 30);
  const double s = rng.uniform(0.8, 1.2), c = rng.uniform(-0.003, 0.003);
  const auto A = quintic_antiderivative({0.35, 0.60, 0.75, 0.92});
  const auto B = quintic_antiderivative({0.10, 0.30, 0.65, 0.85});
  LinearMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  MeshInput m = build_lagrange_mesh(square, d, nullptr, [&](const Vec3 &p, const Vec3 &) {
    return 40 * horner(A, p[0]) + 40 * s * horner(B, p[1]) + c * p[0] * p[1];
  });
  m.field_name = "f";
  m.source = dataset_source("two-triangle", o, d);
  return m;
}

} // namespace hoct
