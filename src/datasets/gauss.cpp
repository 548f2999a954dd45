// `gauss`: a sum of Gaussian bumps and dips on a planar square, quadratic, 722 cells by default
// (the thesis' "Gauss simp40": 722 cells, 28 contour-tree nodes).
#include "datasets/dataset_common.hpp"
#include "datasets/linear_mesh.hpp"
#include "datasets/seeded_random.hpp"

#include <array>
#include <vector>

namespace hoct {

MeshInput generate_gauss(const DatasetOptions &o) {
  const int d = dataset_degree(o, 2, "gauss");
  const long long cells = dataset_cells(o, 722, "gauss");
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(cells / 2.0))));
  SeededRandom rng(o.seed);
  std::vector<std::array<double, 4>> g(5); // cx, cy, width, amplitude
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = {rng.uniform(0.2, 0.8), rng.uniform(0.2, 0.8), rng.uniform(0.12, 0.2),
            (i % 3 == 2 ? -1.0 : 1.0) * rng.uniform(0.4, 1.0)};
  const LinearMesh lm = square_grid(n, n, 1.0 / n, 0, 0, 0.2, o.seed + 11);
  MeshInput m = lagrange_mesh(lm, d, nullptr, [&](const Vec3 &p) {
    double s = 0;
    for (const auto &b : g) {
      const double dx = p[0] - b[0], dy = p[1] - b[1];
      s += b[3] * std::exp(-(dx * dx + dy * dy) / (b[2] * b[2]));
    }
    return s;
  });
  m.field_name = "f";
  m.source = dataset_source("gauss", o, d);
  return m;
}

} // namespace hoct
