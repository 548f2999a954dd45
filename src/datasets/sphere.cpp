// `sphere`: a sum of sines on the unit sphere, curved cubic cells with every node on the sphere,
// about 1,056 cells by default (the thesis' cubic sphere: 1,056 cells, 136 contour-tree nodes,
// equal numbers of maxima and minima). The mesh is a subdivided icosahedron (20 n^2 cells, n
// chosen closest to --cells; 980 by default) with nodes projected radially onto the sphere.
//   f(x, y, z) = sin(a x + t y) + sin(b y + t z) + sin(c z + t x)
// is odd, f(-p) = -f(p), so every maximum has an antipodal minimum; a, b, c in [10.2, 10.8] and the
// coupling t in [0.1, 0.3] depend on the seed (136-ish contour-tree nodes: 138 for seed 1).
#include "datasets/dataset_options.hpp"
#include "datasets/icosphere.hpp"
#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/seeded_random.hpp"

#include <cmath>

namespace hoct {

MeshInput generate_sphere(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "sphere");
  const long long cells = dataset_cells(o, 1056, 20, 20000000, d, "sphere");
  SeededRandom rng(o.seed, 20);
  const double a = rng.uniform(10.2, 10.8), b = rng.uniform(10.2, 10.8),
               c = rng.uniform(10.2, 10.8);
  const double t = rng.uniform(0.1, 0.3);
  const LinearMesh ico = icosphere(icosphere_subdivision(cells));
  MeshInput m = build_lagrange_mesh(
      ico, d,
      [](const Vec3 &p) {
        const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        return Vec3{p[0] / r, p[1] / r, p[2] / r};
      },
      [&](const Vec3 &p, const Vec3 &) {
        return std::sin(a * p[0] + t * p[1]) + std::sin(b * p[1] + t * p[2]) +
               std::sin(c * p[2] + t * p[0]);
      });
  m.field_name = "f";
  m.source = dataset_source("sphere", o, d);
  return m;
}

} // namespace hoct
