// `random`: a smooth random field on a jittered planar grid of the unit square, any degree and
// size (20,000 cubic cells by default; millions too, time and memory linear in the size):
//   f(x, y) = sum over 16 modes of a_m cos(k_m . (x, y) + phi_m),
// wave numbers |k_m| in [6, 30] in random directions, amplitudes a_m in [0.3, 1] / sqrt(|k_m|);
// --frequency F multiplies the wave numbers by F (F^2 times the features on the same square);
// --plateau P raises the node values below their P-th percentile to it (a plateau); --quads
// gives quadrilaterals of order --degree on the same grid instead of triangles.
#include "datasets/dataset_options.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/planar_triangulation.hpp"
#include "datasets/quad_grid.hpp"
#include "datasets/seeded_random.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace hoct {

MeshInput generate_random(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "random");
  const long long cells = dataset_cells(o, 20000, 2, 50000000, d, "random");
  // Triangles: two per grid rectangle; quadrilaterals: one.
  const int n =
      std::max(1, static_cast<int>(std::lround(std::sqrt(cells / (o.quadrilaterals ? 1.0 : 2.0)))));
  const double frequency = o.frequency;
  if (!(frequency > 0 && frequency <= 1000)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", frequency);
    throw Error(std::string("random: --frequency must be in (0, 1000], got ") + got);
  }
  if (!(o.plateau >= 0 && o.plateau < 100)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", o.plateau);
    throw Error(std::string("random: --plateau must be a percentage in [0, 100), got ") + got);
  }
  SeededRandom rng(o.seed, 60);
  struct Mode {
    double kx, ky, phase, amplitude;
  };
  std::array<Mode, 16> modes;
  for (auto &m : modes) {
    const double angle = 2 * std::numbers::pi * rng.uniform(), k = rng.uniform(6, 30);
    m = {frequency * k * std::cos(angle), frequency * k * std::sin(angle),
         2 * std::numbers::pi * rng.uniform(), rng.uniform(0.3, 1.0) / std::sqrt(k)};
  }
  GridSpec grid;
  grid.nx = grid.ny = n;
  grid.hx = grid.hy = 1.0 / n;
  grid.jitter = 0.15;
  grid.seed = o.seed;
  const NodeValue field = [&](const Vec3 &p, const Vec3 &) {
    double f = 0;
    for (const Mode &md : modes)
      f += md.amplitude * std::cos(md.kx * p[0] + md.ky * p[1] + md.phase);
    return f;
  };
  MeshInput m = o.quadrilaterals ? build_quad_grid(grid, d, field)
                                 : build_lagrange_mesh(grid_triangulation(grid), d, nullptr, field);
  if (o.plateau > 0 && !m.values.empty()) {
    // The P-th percentile of the node values (the k-th smallest, k = floor(P n / 100)).
    std::vector<double> sorted(m.values.begin(), m.values.end());
    const std::size_t k =
        std::min(sorted.size() - 1, static_cast<std::size_t>(o.plateau / 100 * sorted.size()));
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    const double level = sorted[k];
    for (double &v : m.values)
      v = std::max(v, level);
  }
  m.field_name = "f";
  m.source = dataset_source("random", o, d);
  return m;
}

} // namespace hoct
