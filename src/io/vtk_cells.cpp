#include "io/vtk_cells.hpp"

#include "poly/lagrange_node_order.hpp"

#include <vector>

namespace hoct {

VtkCellResult add_vtk_cell(MeshInput &m, int64_t type, const int64_t *ids, int64_t n,
                           int64_t num_points, int64_t base, std::string *problem) {
  auto invalid = [&](std::string what) {
    *problem = std::move(what);
    return VtkCellResult::Invalid;
  };
  if (type == 1 || type == 2 || type == 3 || type == 4 || type == 21 || type == 35 || type == 68)
    return VtkCellResult::Skipped;
  if (type != 5 && type != 22 && type != 69)
    return invalid(" has VTK cell type " + std::to_string(type) +
                   ", which is not a triangle (supported: 5 VTK_TRIANGLE, 22 "
                   "VTK_QUADRATIC_TRIANGLE, 69 VTK_LAGRANGE_TRIANGLE)");
  const int degree = degree_from_node_count(n);
  if ((type == 5 && n != 3) || (type == 22 && n != 6) || degree < 1)
    return invalid(" of type " + std::to_string(type) + " has " + std::to_string(n) + " nodes" +
                   (type == 69 && n == 7 ? " (the 7-node 'bubble' triangle is not a complete "
                                           "polynomial space and is not supported)"
                                         : ", not a complete triangle"));
  if (degree > 20)
    return invalid(" has degree " + std::to_string(degree) + " (at most 20 supported)");
  const auto &perm = node_order_to_lattice(NodeOrdering::Vtk, degree);
  thread_local std::vector<int64_t> nodes;
  nodes.assign(static_cast<std::size_t>(n), -1);
  for (int64_t i = 0; i < n; ++i) {
    const int64_t id = ids[i];
    if (id < 0 || id >= num_points)
      return invalid(" refers to point " + std::to_string(id) + ", but the piece has " +
                     std::to_string(num_points) + " points");
    nodes[perm[i]] = base + id;
  }
  m.add_cell(degree, nodes.data());
  return VtkCellResult::Added;
}

} // namespace hoct
