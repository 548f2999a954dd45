// `heater`: a sum of Gaussians on a curved closed surface of genus 0 shaped like a radiator: a
// rounded box (superellipsoid) with fins along its length. Cubic cells with their nodes on the
// exact surface; about 12,500 cells by default (the thesis: 12,438 cells, 268 contour-tree nodes).
#include "datasets/dataset_common.hpp"
#include "datasets/linear_mesh.hpp"
#include "datasets/seeded_random.hpp"

#include <array>
#include <vector>

namespace hoct {

MeshInput generate_heater(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "heater");
  const long long cells = dataset_cells(o, 12438, "heater");
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(cells / 20.0))));
  SeededRandom rng(o.seed);
  // The surface: radius along each unit direction u of a superellipsoid with semi-axes
  // (2, 0.5, 1) and exponent 6, with 5 fins (a cosine ridge pattern along x).
  auto place = [](const Vec3 &p) {
    const double r0 = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const Vec3 u = {p[0] / r0, p[1] / r0, p[2] / r0};
    const double e = 6, ax[3] = {2.0, 0.5, 1.0};
    double s = 0;
    for (int i = 0; i < 3; ++i)
      s += std::pow(std::abs(u[i]) / ax[i], e);
    double r = std::pow(s, -1 / e);
    const double x = r * u[0];
    r *= 1 + 0.05 * std::pow(std::cos(5 * M_PI * x / 4), 2) * (1 - std::abs(u[2]));
    return Vec3{r * u[0], r * u[1], r * u[2]};
  };
  std::vector<std::array<double, 5>> g(220); // centre x, y, z, width, amplitude
  for (auto &b : g) {
    const Vec3 c = place({rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
    b = {c[0], c[1], c[2], rng.uniform(0.12, 0.3), rng.uniform(-1, 1)};
  }
  MeshInput m = lagrange_mesh(icosphere(n), d, place, [&](const Vec3 &p) {
    double s = 0;
    for (const auto &b : g) {
      const double dx = p[0] - b[0], dy = p[1] - b[1], dz = p[2] - b[2];
      s += b[4] * std::exp(-(dx * dx + dy * dy + dz * dz) / (b[3] * b[3]));
    }
    return s;
  });
  m.field_name = "temperature";
  m.source = dataset_source("heater", o, d);
  return m;
}

} // namespace hoct
