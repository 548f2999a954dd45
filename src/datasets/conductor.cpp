// `conductor`: a temperature field with the degeneracies of FEM data with fixed-value
// boundaries, on a planar Pi-shaped plate (a top bar on two legs; genus 0), quadratic, about
// 4,300 cells by default (the thesis: 4,298 cells, 530 contour-tree nodes). It holds
//  - a plateau: a clamp on the top bar where the temperature is exactly constant (constant cells
//    and many equal node values),
//  - ridges: in the lower part of each leg the field is exactly 0.2 + 0.8 (1 - 4 (x - c)^2),
//    a function of x alone, so cells there are exact quadratics with a critical segment x = c,
//  - ordinary cells: smooth bumps and a blend on the top bar.
#include "datasets/dataset_common.hpp"
#include "datasets/linear_mesh.hpp"
#include "datasets/seeded_random.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace hoct {

MeshInput generate_conductor(const DatasetOptions &o) {
  const int d = dataset_degree(o, 2, "conductor");
  const long long cells = dataset_cells(o, 4298, "conductor");
  // The plate [0,3] x [0,3] minus the gap [1,2] x [0,2]: 7 unit squares, 14 N^2 cells.
  const int N = std::max(2, static_cast<int>(std::lround(std::sqrt(cells / 14.0))));
  SeededRandom rng(o.seed);
  std::vector<std::array<double, 4>> bumps(6);
  for (auto &b : bumps)
    b = {rng.uniform(0.2, 2.8), rng.uniform(2.1, 2.9), rng.uniform(0.15, 0.3),
         rng.uniform(-0.15, 0.25)};
  auto keep = [N](int i, int j) { return !(i >= N && i < 2 * N && j < 2 * N); };
  const LinearMesh lm = square_grid(3 * N, 3 * N, 1.0 / N, 0, 0, 0.15, o.seed + 3, keep);
  const double clamp_x0 = 1.25, clamp_x1 = 1.75, clamp_y0 = 2.4;
  auto f = [&](const Vec3 &p) {
    const double x = p[0], y = p[1];
    // Ridge in each leg (x in [0,1] or [2,3]).
    const double c = x < 1.5 ? 0.5 : 2.5;
    const double ridge = 0.2 + 0.8 * (1 - 4 * (x - c) * (x - c));
    // Top bar: the clamp temperature 0.3 plus a rise with the squared distance from the clamp,
    // and bumps.
    const double dx = std::max({clamp_x0 - x, 0.0, x - clamp_x1});
    const double dy = std::max(clamp_y0 - y, 0.0);
    double top = 0.3 + 0.6 * (dx * dx + dy * dy);
    for (const auto &b : bumps) {
      const double ex = x - b[0], ey = y - b[1];
      top += b[3] * std::exp(-(ex * ex + ey * ey) / (b[2] * b[2])) * (dx * dx + dy * dy > 0);
    }
    if (dx == 0 && dy == 0)
      return 0.3; // the clamp: exactly constant
    if (y <= 1.2)
      return ridge;
    if (y >= 2.0)
      return top;
    const double s = (y - 1.2) / 0.8, w = s * s * (3 - 2 * s); // smoothstep
    return (1 - w) * ridge + w * top;
  };
  MeshInput m = lagrange_mesh(lm, d, nullptr, f);
  m.field_name = "temperature";
  m.source = dataset_source("conductor", o, d);
  return m;
}

} // namespace hoct
