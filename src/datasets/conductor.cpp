// `conductor`: a temperature field with the degeneracies of FEM output with fixed-value boundary
// conditions, quadratic, about 4,298 cells by default (the thesis' conductor: 4,298 quadratic
// cells, 530 contour-tree nodes, degenerate patches on its top). The domain is a planar Pi-shaped
// plate (genus 0): the top bar [0,3] x [2,3] on two legs [0,1] x [0,2] and [2,3] x [0,2], a
// jittered grid of 14 Nx Ny cells (Nx, Ny cells per unit along x, y). The temperature T is one
// continuous function sampled at the nodes:
//  - a clamp R = [1.2, 1.8] x [2.55, 3] held at T = 0.3: every cell inside R is exactly constant
//    (a plateau);
//  - elsewhere T = 0.3 + (1 - exp(-dist(p, R)^2 / 0.16)) G(p), where G is 0.35 plus a hot spot
//    in each leg (at (0.5, 1.1) and (2.5, 1.1)) plus small seed-dependent bumps on the top bar;
//  - in the bottom of each leg (y <= 0.5) T is exactly the ridge 0.55 - 1.2 (x - c)^2 with
//    c = 0.5 or 2.5: every cell there is exactly this quadratic, and where it straddles x = c its
//    critical set is the segment x = c; for 0.5 < y < 0.9 a smoothstep in y blends the ridge into
//    the field above, so T stays continuous. The legs' sides there are held at T = 0.25 (a
//    fixed-value boundary: constant boundary edges).
// Cells straddling the clamp's boundary get the undershoot of quadratic interpolation (cells with
// five nodes on the plateau are exact valleys 0.3 + lambda l (l - h/2)), as FEM data does. The
// seed moves the top bar's bumps, the hot spots' strengths (within 5%) and the grid's jitter.
#include "datasets/dataset_options.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/planar_triangulation.hpp"
#include "datasets/seeded_random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hoct {

MeshInput generate_conductor(const DatasetOptions &o) {
  const int d = dataset_degree(o, 2, "conductor");
  const long long cells = dataset_cells(o, 4298, 14, 20000000, d, "conductor");
  // 14 Nx Ny cells with Ny = Nx or Nx + 1, closest to the target.
  int nx = 1, ny = 1;
  long long best = -1;
  for (int a = 1; 14LL * a * a <= 4 * cells + 14; ++a)
    for (int b = a; b <= a + 1; ++b)
      if (const long long miss = std::llabs(14LL * a * b - cells); best < 0 || miss < best) {
        best = miss;
        nx = a;
        ny = b;
      }
  SeededRandom rng(o.seed, 50);
  struct Bump {
    double x, y, width, amplitude;
  };
  std::vector<Bump> bumps(10);
  for (auto &b : bumps)
    b = {rng.uniform(0.1, 2.9), rng.uniform(2.05, 2.95), rng.uniform(0.1, 0.25),
         rng.uniform(-0.12, 0.12)};
  const double hot[2] = {rng.uniform(0.95, 1.05), rng.uniform(0.95, 1.05)};

  GridSpec grid;
  grid.nx = 3 * nx;
  grid.ny = 3 * ny;
  grid.hx = 1.0 / nx;
  grid.hy = 1.0 / ny;
  grid.jitter = 0.15;
  grid.seed = o.seed;
  grid.keep = [nx, ny](int i, int j) { return !(i >= nx && i < 2 * nx && j < 2 * ny); };

  const double clamp_x0 = 1.2, clamp_x1 = 1.8, clamp_y0 = 2.55, clamp_value = 0.3;
  const double ridge_top = 0.5, blend_top = 0.9;
  auto above = [&](double x, double y) {
    const double dx = std::max({clamp_x0 - x, 0.0, x - clamp_x1}), dy = std::max(clamp_y0 - y, 0.0);
    const double dist2 = dx * dx + dy * dy;
    if (dist2 == 0)
      return clamp_value;
    double g = 0.35;
    for (int k = 0; k < 2; ++k) {
      const double ex = x - (k ? 2.5 : 0.5), ey = y - 1.1;
      g += hot[k] * std::exp(-(ex * ex + ey * ey) / 0.2);
    }
    for (const Bump &b : bumps) {
      const double ex = x - b.x, ey = y - b.y;
      g += b.amplitude * std::exp(-(ex * ex + ey * ey) / (b.width * b.width));
    }
    return clamp_value + (1 - std::exp(-dist2 / 0.16)) * g;
  };
  auto temperature = [&](const Vec3 &p, const Vec3 &) {
    const double x = p[0], y = p[1];
    if (y >= blend_top || (x > 1 && x < 2))
      return above(x, y);
    const double c = x < 1.5 ? 0.5 : 2.5;
    const double ridge = 0.55 - 1.2 * (x - c) * (x - c);
    if (y <= ridge_top)
      return ridge;
    const double s = (y - ridge_top) / (blend_top - ridge_top), w = s * s * (3 - 2 * s);
    return (1 - w) * ridge + w * above(x, y);
  };
  MeshInput m = build_lagrange_mesh(grid_triangulation(grid), d, nullptr, temperature);
  m.field_name = "temperature";
  m.source = dataset_source("conductor", o, d);
  return m;
}

} // namespace hoct
