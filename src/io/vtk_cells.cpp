#include "io/vtk_cells.hpp"

#include "poly/lagrange_node_order.hpp"

#include <vector>

namespace hoct {

VtkCellResult vtk_cell_nodes(int64_t type, const int64_t *ids, int64_t n, int64_t num_points,
                             int64_t base, int64_t *out, int *degree_out, std::string *problem) {
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
  if (degree > kMaxVtkCellDegree)
    return invalid(" has degree " + std::to_string(degree) + " (at most " +
                   std::to_string(kMaxVtkCellDegree) + " supported)");
  // The permutation of the previous cell's degree, kept (meshes have one degree or few).
  thread_local int cached_degree = 0;
  thread_local const std::vector<int> *cached_perm = nullptr;
  if (degree != cached_degree) {
    cached_perm = &node_order_to_lattice(NodeOrdering::Vtk, degree);
    cached_degree = degree;
  }
  const int *perm = cached_perm->data();
  for (int64_t i = 0; i < n; ++i) {
    const int64_t id = ids[i];
    if (id < 0 || id >= num_points)
      return invalid(" refers to point " + std::to_string(id) + ", but the piece has " +
                     std::to_string(num_points) + " points");
    out[perm[i]] = base + id;
  }
  *degree_out = degree;
  return VtkCellResult::Added;
}

VtkCellResult add_vtk_cell(MeshInput &m, int64_t type, const int64_t *ids, int64_t n,
                           int64_t num_points, int64_t base, std::string *problem) {
  int64_t nodes[kMaxVtkCellNodes];
  int degree = 0;
  const VtkCellResult r = vtk_cell_nodes(type, ids, n, num_points, base, nodes, &degree, problem);
  if (r == VtkCellResult::Added)
    m.add_cell(degree, nodes);
  return r;
}

} // namespace hoct
