#include "io/vtk_cells.hpp"

#include "poly/lagrange_node_order.hpp"
#include "poly/quad_basis.hpp"

#include <cmath>
#include <vector>

namespace hoct {
namespace {

// The permutation of the previous cell's shape and degree, kept (meshes have few of them).
const int *cached_order(int shape, int degree) {
  thread_local int cached_shape = -1, cached_degree = 0;
  thread_local const std::vector<int> *cached_perm = nullptr;
  if (shape != cached_shape || degree != cached_degree) {
    cached_perm = shape == 0   ? &node_order_to_lattice(NodeOrdering::Vtk, degree)
                  : shape == 1 ? &quad_node_order_to_tensor(NodeOrdering::Vtk, degree)
                               : &serendipity_node_order(NodeOrdering::Vtk, degree);
    cached_shape = shape;
    cached_degree = degree;
  }
  return cached_perm->data();
}

int square_root(int64_t n) {
  const int64_t r = static_cast<int64_t>(std::llround(std::sqrt(static_cast<double>(n))));
  return r * r == n ? static_cast<int>(r) : -1;
}

} // namespace

VtkCellResult vtk_cell_nodes(int64_t type, const int64_t *ids, int64_t n, int64_t num_points,
                             int64_t base, int64_t *out, int *degree_out, CellKind *kind_out,
                             std::string *problem) {
  auto invalid = [&](std::string what) {
    *problem = std::move(what);
    return VtkCellResult::Invalid;
  };
  if (type == 1 || type == 2 || type == 3 || type == 4 || type == 21 || type == 35 || type == 68 ||
      type == 75)
    return VtkCellResult::Skipped;
  int degree = -1, shape = 0;
  CellKind kind = CellKind::LagrangeTriangle;
  switch (type) {
  case 5:
  case 22:
  case 69:
  case 76:
    degree = degree_from_node_count(n);
    if ((type == 5 && n != 3) || (type == 22 && n != 6) || degree < 1)
      return invalid(" of type " + std::to_string(type) + " has " + std::to_string(n) + " nodes" +
                     (type == 69 && n == 7 ? " (the 7-node 'bubble' triangle is not a complete "
                                             "polynomial space and is not supported)"
                                           : ", not a complete triangle"));
    if (degree > kMaxVtkCellDegree)
      return invalid(" has degree " + std::to_string(degree) + " (at most " +
                     std::to_string(kMaxVtkCellDegree) + " supported)");
    kind = type == 76 ? CellKind::BezierTriangle : CellKind::LagrangeTriangle;
    break;
  case 9:
  case 28:
  case 70:
  case 77: {
    const int root = square_root(n);
    degree = root - 1;
    if ((type == 9 && n != 4) || (type == 28 && n != 9) || degree < 1)
      return invalid(" of type " + std::to_string(type) + " has " + std::to_string(n) +
                     " nodes, not (p+1)^2 for a quadrilateral of order (p, p)" +
                     (type == 70 || type == 77
                          ? " (cells of different orders along their two directions, "
                            "HigherOrderDegrees, are not supported)"
                          : ""));
    if (degree > kMaxQuadDegree)
      return invalid(" is a quadrilateral of order " + std::to_string(degree) + " (at most " +
                     std::to_string(kMaxQuadDegree) + " supported)");
    kind = type == 77 ? CellKind::BezierQuadrilateral : CellKind::LagrangeQuadrilateral;
    shape = 1;
    break;
  }
  case 23:
    if (n != 8)
      return invalid(" of type 23 (VTK_QUADRATIC_QUAD) has " + std::to_string(n) + " nodes, not 8");
    degree = 2;
    kind = CellKind::SerendipityQuadrilateral;
    shape = 2;
    break;
  default:
    return invalid(
        " has VTK cell type " + std::to_string(type) +
        ", which is not a supported surface cell (supported: triangles 5, 22, 69, 76 and "
        "quadrilaterals 9, 23, 28, 70, 77: VTK_TRIANGLE, VTK_QUADRATIC_TRIANGLE, "
        "VTK_LAGRANGE_TRIANGLE, VTK_BEZIER_TRIANGLE, VTK_QUAD, VTK_QUADRATIC_QUAD, "
        "VTK_BIQUADRATIC_QUAD, VTK_LAGRANGE_QUADRILATERAL, VTK_BEZIER_QUADRILATERAL)");
  }
  const int *perm = cached_order(shape, degree);
  for (int64_t i = 0; i < n; ++i) {
    const int64_t id = ids[i];
    if (id < 0 || id >= num_points)
      return invalid(" refers to point " + std::to_string(id) + ", but the piece has " +
                     std::to_string(num_points) + " points");
    out[perm[i]] = base + id;
  }
  *degree_out = degree;
  *kind_out = kind;
  return VtkCellResult::Added;
}

VtkCellResult add_vtk_cell(MeshInput &m, int64_t type, const int64_t *ids, int64_t n,
                           int64_t num_points, int64_t base, std::string *problem) {
  int64_t nodes[kMaxVtkCellNodes];
  int degree = 0;
  CellKind kind = CellKind::LagrangeTriangle;
  const VtkCellResult r =
      vtk_cell_nodes(type, ids, n, num_points, base, nodes, &degree, &kind, problem);
  if (r == VtkCellResult::Added)
    m.add_cell(kind, degree, nodes);
  return r;
}

} // namespace hoct
