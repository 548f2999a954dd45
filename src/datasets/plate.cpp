// `plate`: a smooth field on a perforated plate, the unit square with 10 x 10 square holes (a
// perforated heat sink): a domain with 100 holes, whose level-set graph is a Reeb graph with
// loops around the holes. The plate is a grid of n x n squares (n a multiple of 10, two
// triangles each), each of its 10 x 10 blocks of squares without the middle half of its squares
// in each direction; any degree and size (20,000 cubic cells by default). The field:
//   f(x, y) = 0.8 x + 0.5 y + 0.15 sum over 6 modes of cos(k_m . (x, y) + phi_m) / |k_m| * 6,
// a tilt with gentle random waves (|k_m| in [4, 12]), so most holes carry one loop.
#include "datasets/dataset_options.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/seeded_random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace hoct {

MeshInput generate_plate(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "plate");
  const long long cells = dataset_cells(o, 20000, 1500, 50000000, d, "plate");
  // 2 n^2 * 3/4 cells (a quarter of each block is hole): n from the target, a multiple of 20.
  const int n = std::max(20, 20 * static_cast<int>(std::lround(std::sqrt(cells / 1.5) / 20)));
  const int block = n / 10;
  auto in_hole = [&](int i, int j) {
    const int a = i % block, b = j % block;
    return a >= block / 4 && a < block - block / 4 && b >= block / 4 && b < block - block / 4;
  };
  LinearMesh plate;
  std::vector<int64_t> id(static_cast<std::size_t>(n + 1) * (n + 1), -1);
  auto vertex = [&](int i, int j) {
    int64_t &v = id[static_cast<std::size_t>(j) * (n + 1) + i];
    if (v < 0) {
      v = static_cast<int64_t>(plate.vertices.size());
      plate.vertices.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n, 0});
    }
    return v;
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (in_hole(i, j))
        continue;
      const int64_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                    e = vertex(i, j + 1);
      plate.triangles.push_back({a, b, c});
      plate.triangles.push_back({a, c, e});
    }
  SeededRandom rng(o.seed, 70);
  struct Mode {
    double kx, ky, phase, amplitude;
  };
  std::array<Mode, 6> modes;
  for (auto &m : modes) {
    const double angle = 2 * std::numbers::pi * rng.uniform(), k = rng.uniform(4, 12);
    m = {k * std::cos(angle), k * std::sin(angle), 2 * std::numbers::pi * rng.uniform(),
         0.15 * 6 / k};
  }
  MeshInput m = build_lagrange_mesh(plate, d, nullptr, [&](const Vec3 &p, const Vec3 &) {
    double f = 0.8 * p[0] + 0.5 * p[1];
    for (const Mode &md : modes)
      f += md.amplitude * std::cos(md.kx * p[0] + md.ky * p[1] + md.phase) / 6;
    return f;
  });
  m.field_name = "f";
  m.source = dataset_source("plate", o, d);
  return m;
}

} // namespace hoct
