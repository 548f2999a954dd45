// `random`: a smooth random field on a jittered planar grid of the unit square, any degree and
// size (20,000 cubic cells by default; millions in seconds, memory linear in the size):
//   f(x, y) = sum over 16 modes of a_m cos(k_m . (x, y) + phi_m),
// wave numbers |k_m| in [6, 30] in random directions, amplitudes a_m in [0.3, 1] / sqrt(|k_m|);
// --frequency F multiplies the wave numbers by F (F^2 times the features on the same square).
#include "datasets/dataset_options.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/planar_triangulation.hpp"
#include "datasets/seeded_random.hpp"
#include "error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace hoct {

MeshInput generate_random(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "random");
  const long long cells = dataset_cells(o, 20000, 2, 50000000, d, "random");
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(cells / 2.0))));
  const double frequency = o.frequency;
  if (!(frequency > 0 && frequency <= 1000)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", frequency);
    throw Error(std::string("random: --frequency must be in (0, 1000], got ") + got);
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
  MeshInput m =
      build_lagrange_mesh(grid_triangulation(grid), d, nullptr, [&](const Vec3 &p, const Vec3 &) {
        double f = 0;
        for (const Mode &md : modes)
          f += md.amplitude * std::cos(md.kx * p[0] + md.ky * p[1] + md.phase);
        return f;
      });
  m.field_name = "f";
  m.source = dataset_source("random", o, d);
  return m;
}

} // namespace hoct
