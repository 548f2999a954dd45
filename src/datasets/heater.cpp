// `heater`: a sum of Gaussians on the closed surface of a radiator-like body, cubic cells with
// every node on the exact surface, about 12,438 cells by default (the thesis' heater: 12,438 cubic
// cells, 268 contour-tree nodes).
//
// The surface (genus 0) is the image of the cube [-1,1]^3's surface q under
//   u = q / (q_x^4 + q_y^4 + q_z^4)^(1/4)          (onto the unit superellipsoid, a rounded cube)
//   X = L u_x,  Y = T(X) u_y,  Z = H u_z          (a rounded panel, length 2L, height 2H)
//   T(X) = T0 (1 + F (1/2 + cos(2 pi X / P) / 2)^2)  (thickness with vertical fins every P)
// with L = 2, H = 1, T0 = 0.3, F = 0.6, P = 0.5. Both steps are orientation-preserving
// diffeomorphisms (the second has Jacobian determinant L T(X) H > 0), so the cube's outward
// triangulation (datasets/box_surface) maps to an outward surface mesh. The cube's grid
// resolution per axis follows the panel's extent, so cells are nearly isotropic. Curved cells
// must resolve the fins and the rounded edges not to fold: the fins are lowered on coarse meshes
// (see below), and --cells is at least 600.
// The field: 240 Gaussians exp(-|p - c|^2 / w^2) centred on the surface, widths in [0.1, 0.25],
// amplitudes in [-1, 1].
#include "datasets/box_surface.hpp"
#include "datasets/dataset_options.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/seeded_random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace hoct {
namespace {

constexpr double kLength = 2, kHeight = 1, kThickness = 0.3, kFin = 0.6, kFinPeriod = 0.5;

// The surface with fin height `fin` (kFin at full resolution).
Vec3 heater_surface(const Vec3 &q, double fin) {
  const double q2[3] = {q[0] * q[0], q[1] * q[1], q[2] * q[2]};
  const double s = q2[0] * q2[0] + q2[1] * q2[1] + q2[2] * q2[2];
  const double k = std::pow(s, -1.0 / 4.0);
  const double x = kLength * k * q[0];
  const double c = 0.5 + 0.5 * std::cos(2 * std::numbers::pi * x / kFinPeriod);
  return {x, kThickness * (1 + fin * c * c) * k * q[1], kHeight * k * q[2]};
}

// Cube grid resolution (nx, ny, nz) with 4 (nx ny + ny nz + nz nx) cells closest to `cells`,
// intervals proportional to the panel's extents 2L, 2 T0 (1 + F/2), 2H.
std::array<int, 3> heater_grid(long long cells) {
  const double extent[3] = {2 * kLength, 2 * kThickness * (1 + kFin / 2), 2 * kHeight};
  std::array<int, 3> best = {1, 1, 1};
  long long best_miss = -1;
  for (double h = 2 * extent[0]; h > 1e-5; h *= 0.995) {
    std::array<int, 3> n;
    for (int a = 0; a < 3; ++a)
      n[a] = std::max(1, static_cast<int>(std::lround(extent[a] / h)));
    const long long total = 4LL * (1LL * n[0] * n[1] + 1LL * n[1] * n[2] + 1LL * n[2] * n[0]);
    const long long miss = std::llabs(total - cells);
    if (best_miss < 0 || miss < best_miss) {
      best = n;
      best_miss = miss;
    }
    if (total > 2 * cells)
      break;
  }
  return best;
}

} // namespace

MeshInput generate_heater(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "heater");
  const long long cells = dataset_cells(o, 12438, 600, 20000000, d, "heater");
  SeededRandom rng(o.seed, 40);
  struct Gaussian {
    Vec3 centre;
    double width, amplitude;
  };
  std::vector<Gaussian> gaussians(240);
  for (auto &g : gaussians) {
    // A point of the cube's surface: a random point of [-1,1]^3 pushed onto a random face.
    Vec3 q = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const int axis = static_cast<int>(rng.next() % 3);
    q[axis] = rng.sign();
    g.centre = heater_surface(q, kFin);
    g.width = rng.uniform(0.1, 0.25);
    g.amplitude = rng.uniform(-1, 1);
  }
  const auto n = heater_grid(cells);
  // Cells of degree >= 3 follow the fins with 5 or more cells per fin period (quadratic ones
  // with 6.5); coarser meshes get lower fins (none below 3, resp. 4.5, cells per period) so that
  // no cell folds.
  const double per_period = kFinPeriod / (2 * kLength / n[0]);
  const double needed = 3 * std::max(1.0, 3.0 / d);
  const double fin = kFin * std::clamp((per_period - needed) / 2, 0.0, 1.0);
  const auto place = [fin](const Vec3 &q) { return heater_surface(q, fin); };
  MeshInput m = build_lagrange_mesh(
      box_surface(n[0], n[1], n[2]), d, place, [&](const Vec3 &p, const Vec3 &) {
        double f = 0;
        for (const Gaussian &g : gaussians) {
          const double dx = p[0] - g.centre[0], dy = p[1] - g.centre[1], dz = p[2] - g.centre[2];
          f += g.amplitude * std::exp(-(dx * dx + dy * dy + dz * dz) / (g.width * g.width));
        }
        return f;
      });
  m.field_name = "temperature";
  m.source = dataset_source("heater", o, d);
  return m;
}

} // namespace hoct
