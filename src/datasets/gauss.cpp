// `gauss`: a sum of Gaussian bumps and dips with a gentle tilt on a planar disk, quadratic, about
// 722 cells by default: modelled on the thesis' "Gauss simp40" (722 quadratic cells, 28
// contour-tree nodes). The disk is a jittered ring triangulation (datasets/planar_triangulation).
#include "datasets/dataset_options.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/planar_triangulation.hpp"
#include "datasets/seeded_random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace hoct {

MeshInput generate_gauss(const DatasetOptions &o) {
  const int d = dataset_degree(o, 2, "gauss");
  const long long cells = dataset_cells(o, 722, 6, 20000000, d, "gauss");
  // 6 rings^2 cells: 11 rings give 726 cells.
  const int rings = std::max(1, static_cast<int>(std::lround(std::sqrt(cells / 6.0))));
  SeededRandom rng(o.seed, 10);
  struct Bump {
    double x, y, width, amplitude;
  };
  // Centres at least 0.3 apart (rejection sampling), so each bump is its own extremum.
  std::vector<Bump> bumps;
  while (bumps.size() < 8) {
    const double r = 0.65 * std::sqrt(rng.uniform()), a = 2 * std::numbers::pi * rng.uniform();
    const double x = r * std::cos(a), y = r * std::sin(a);
    const double width = rng.uniform(0.15, 0.25);
    const double amplitude = bumps.size() < 5 ? rng.uniform(0.5, 1.0) : -rng.uniform(0.4, 0.8);
    const bool apart = std::all_of(bumps.begin(), bumps.end(), [&](const Bump &b) {
      return (b.x - x) * (b.x - x) + (b.y - y) * (b.y - y) >= 0.3 * 0.3;
    });
    if (apart)
      bumps.push_back({x, y, width, amplitude});
  }
  const double tilt_angle = 2 * std::numbers::pi * rng.uniform(), tilt = 0.15;
  const double tx = tilt * std::cos(tilt_angle), ty = tilt * std::sin(tilt_angle);
  const LinearMesh disk = ring_disk(rings, 1.0, {0, 0, 0}, 0.18, o.seed);
  MeshInput m = build_lagrange_mesh(disk, d, nullptr, [&](const Vec3 &p, const Vec3 &) {
    double f = tx * p[0] + ty * p[1];
    for (const Bump &b : bumps) {
      const double dx = p[0] - b.x, dy = p[1] - b.y;
      f += b.amplitude * std::exp(-(dx * dx + dy * dy) / (b.width * b.width));
    }
    return f;
  });
  m.field_name = "f";
  m.source = dataset_source("gauss", o, d);
  return m;
}

} // namespace hoct
