// `random`: a smooth random field, a sum of 16 cosine modes with random wave vectors, on a
// jittered planar grid of the unit square. Any degree and size (up to millions of cells).
#include "datasets/dataset_common.hpp"
#include "datasets/linear_mesh.hpp"
#include "datasets/seeded_random.hpp"

#include <array>
#include <vector>

namespace hoct {

MeshInput generate_random(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "random");
  const long long cells = dataset_cells(o, 20000, "random");
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(cells / 2.0))));
  SeededRandom rng(o.seed);
  std::vector<std::array<double, 4>> modes(16); // kx, ky, phase, amplitude
  for (auto &m : modes) {
    const double angle = rng.uniform(0, 2 * M_PI), k = rng.uniform(2, 14);
    m = {k * std::cos(angle), k * std::sin(angle), rng.uniform(0, 2 * M_PI),
         rng.uniform(0.3, 1.0) / std::sqrt(k)};
  }
  const LinearMesh lm = square_grid(n, n, 1.0 / n, 0, 0, 0.15, o.seed + 7);
  MeshInput m = lagrange_mesh(lm, d, nullptr, [&](const Vec3 &p) {
    double s = 0;
    for (const auto &md : modes)
      s += md[3] * std::cos(md[0] * p[0] + md[1] * p[1] + md[2]);
    return s;
  });
  m.field_name = "f";
  m.source = dataset_source("random", o, d);
  return m;
}

} // namespace hoct
