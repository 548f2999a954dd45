// `two-triangle`: the thesis' toy, two degree-5 cells sharing an edge. The unit square is split on
// its diagonal (0,0)-(1,1); the field is one global quintic
//   f(x, y) = A(x) + s B(y),   A' = (x - .35)(x - .60)(x - .75)(x - .92),
//                              B' = (y - .10)(y - .30)(y - .65)(y - .85),
// so its 16 critical points are exactly the grid (r_i, s_j): 11 below the diagonal (cell 0), 5
// above (cell 1), none on it; minima where A'' > 0 and s B'' > 0, maxima where both < 0, saddles
// otherwise. The seed scales s in [0.8, 1.2]. With --degree >= 5 the cells represent f exactly.
#include "datasets/dataset_common.hpp"
#include "datasets/seeded_random.hpp"
#include "poly/lattice.hpp"

#include <array>
#include <vector>

namespace hoct {
namespace {

// Antiderivative (zero at 0) of prod (x - r_i), by expanding the product in monomials.
double antiderivative(const std::array<double, 4> &roots, double x) {
  std::vector<double> p = {1.0};
  for (double r : roots) {
    std::vector<double> q(p.size() + 1, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      q[i] -= r * p[i];
      q[i + 1] += p[i];
    }
    p = q;
  }
  double s = 0, xp = x;
  for (std::size_t i = 0; i < p.size(); ++i, xp *= x)
    s += p[i] * xp / static_cast<double>(i + 1);
  return s;
}

} // namespace

const std::array<double, 4> kTwoTriangleRootsX = {0.35, 0.60, 0.75, 0.92};
const std::array<double, 4> kTwoTriangleRootsY = {0.10, 0.30, 0.65, 0.85};

MeshInput generate_two_triangle(const DatasetOptions &o) {
  if (o.cells > 0 && o.cells != 2)
    throw Error("two-triangle: the dataset has exactly 2 cells (--cells does not apply)");
  const int d = dataset_degree(o, 5, "two-triangle");
  SeededRandom rng(o.seed);
  const double scale = rng.uniform(0.8, 1.2);
  auto f = [&](double x, double y) {
    return 40 *
           (antiderivative(kTwoTriangleRootsX, x) + scale * antiderivative(kTwoTriangleRootsY, y));
  };
  MeshInput m;
  // Lattice points of the two cells; shared points (the diagonal) created once.
  const Vec3 corners[2][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  std::vector<std::pair<std::array<long long, 2>, int64_t>> made;
  auto point = [&](double x, double y) {
    const std::array<long long, 2> key = {std::llround(x * 1e9), std::llround(y * 1e9)};
    for (const auto &[k, id] : made)
      if (k == key)
        return id;
    m.points.push_back({x, y, 0});
    m.values.push_back(f(x, y));
    made.push_back({key, static_cast<int64_t>(m.points.size() - 1)});
    return made.back().second;
  };
  std::vector<int64_t> nodes(lattice_size(d));
  for (const auto &c : corners) {
    for (int i = 0; i < lattice_size(d); ++i) {
      const auto q = lattice_point(d, i);
      const double u = static_cast<double>(q[0]) / d, v = static_cast<double>(q[1]) / d;
      nodes[i] = point((1 - u - v) * c[0][0] + u * c[1][0] + v * c[2][0],
                       (1 - u - v) * c[0][1] + u * c[1][1] + v * c[2][1]);
    }
    m.add_cell(d, nodes.data());
  }
  m.field_name = "f";
  m.source = dataset_source("two-triangle", o, d);
  return m;
}

} // namespace hoct
