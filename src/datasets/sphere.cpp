// `sphere`: a sum of sines on the unit sphere, curved cubic cells with their nodes on the sphere
// (the thesis: 1,056 cubic cells, 136 contour-tree nodes; odd field, so maxima and minima pair up).
#include "datasets/dataset_common.hpp"
#include "datasets/linear_mesh.hpp"
#include "datasets/seeded_random.hpp"

namespace hoct {

MeshInput generate_sphere(const DatasetOptions &o) {
  const int d = dataset_degree(o, 3, "sphere");
  const long long cells = dataset_cells(o, 1056, "sphere");
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(cells / 20.0))));
  SeededRandom rng(o.seed);
  // Frequencies near 10.5 with a seed-dependent tilt; sin is odd, so f(-p) = -f(p).
  const double a = 10.5 + rng.uniform(-0.3, 0.3), b = 10.5 + rng.uniform(-0.3, 0.3),
               c = 10.5 + rng.uniform(-0.3, 0.3), t = rng.uniform(0.1, 0.3);
  const LinearMesh lm = icosphere(n);
  MeshInput m = lagrange_mesh(
      lm, d,
      [](const Vec3 &p) {
        const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        return Vec3{p[0] / r, p[1] / r, p[2] / r};
      },
      [&](const Vec3 &p) {
        return std::sin(a * p[0] + t * p[1]) + std::sin(b * p[1] + t * p[2]) +
               std::sin(c * p[2] + t * p[0]);
      });
  m.field_name = "f";
  m.source = dataset_source("sphere", o, d);
  return m;
}

} // namespace hoct
