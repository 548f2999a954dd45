#include "datasets/quad_grid.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace hoct {

MeshInput build_quad_grid(const GridSpec &grid, int p, const NodeValue &value) {
  if (p < 1 || p > 10)
    throw Error("quadrilateral grid: order must be between 1 and 10, got " + std::to_string(p));
  if (grid.keep)
    throw Error("quadrilateral grid: every rectangle must be kept");
  const LinearMesh corners = grid_triangulation(grid); // vertex (i, j) is i + (nx + 1) j
  const int64_t nx = grid.nx, ny = grid.ny, mx = nx * p, my = ny * p;
  auto corner = [&](int64_t i, int64_t j) -> const Vec3 & {
    return corners.vertices[static_cast<std::size_t>(i + (nx + 1) * j)];
  };
  MeshInput m;
  m.points.resize(static_cast<std::size_t>((mx + 1) * (my + 1)));
  m.values.resize(m.points.size());
  for (int64_t J = 0; J <= my; ++J)
    for (int64_t I = 0; I <= mx; ++I) {
      // The node's cell (the last one on the far sides) and its place in the cell.
      const int64_t ci = std::min(I / p, nx - 1), cj = std::min(J / p, ny - 1);
      const double s = static_cast<double>(I - ci * p) / p, t = static_cast<double>(J - cj * p) / p;
      const Vec3 &a = corner(ci, cj), &b = corner(ci + 1, cj), &c = corner(ci + 1, cj + 1),
                 &d = corner(ci, cj + 1);
      Vec3 x;
      for (int k = 0; k < 3; ++k)
        x[k] = (1 - s) * (1 - t) * a[k] + s * (1 - t) * b[k] + s * t * c[k] + (1 - s) * t * d[k];
      const Vec3 flat{grid.x0 + static_cast<double>(I) * grid.hx / p,
                      grid.y0 + static_cast<double>(J) * grid.hy / p, 0.0};
      const std::size_t id = static_cast<std::size_t>(I + (mx + 1) * J);
      m.points[id] = x;
      m.values[id] = value(x, flat);
    }
  const int n = (p + 1) * (p + 1);
  std::vector<int64_t> nodes(static_cast<std::size_t>(n));
  m.cell_offsets.reserve(static_cast<std::size_t>(nx * ny) + 1);
  m.cell_nodes.reserve(static_cast<std::size_t>(nx * ny * n));
  for (int64_t cj = 0; cj < ny; ++cj)
    for (int64_t ci = 0; ci < nx; ++ci) {
      for (int j = 0; j <= p; ++j)
        for (int i = 0; i <= p; ++i)
          nodes[static_cast<std::size_t>(i + (p + 1) * j)] = (ci * p + i) + (mx + 1) * (cj * p + j);
      m.add_cell(CellKind::LagrangeQuadrilateral, p, nodes.data());
    }
  return m;
}

} // namespace hoct
