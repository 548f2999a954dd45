// VTK's surface cells as MeshInput cells: the part of reading VTK data that does not depend on
// where the cells come from (a .vtu file in io/vtu_reader, a vtkUnstructuredGrid in the ParaView
// plugin).
#pragma once

#include "mesh/mesh_input.hpp"

#include <cstdint>
#include <string>

namespace hoct {

enum class VtkCellResult { Added, Skipped, Invalid };

// The largest degree read, and its node count.
constexpr int kMaxVtkCellDegree = 20;
constexpr int kMaxVtkCellNodes = (kMaxVtkCellDegree + 1) * (kMaxVtkCellDegree + 2) / 2;

// Appends the VTK cell of type `type` whose n point ids (VTK node order, relative to `base`) are
// `ids` to m, its nodes converted to canonical order (mesh/mesh_input.hpp). Added: triangles
// VTK_TRIANGLE (5), VTK_QUADRATIC_TRIANGLE (22), VTK_LAGRANGE_TRIANGLE (69) and
// VTK_BEZIER_TRIANGLE (76) of degree up to 20; quadrilaterals VTK_QUAD (9), VTK_QUADRATIC_QUAD
// (23, serendipity), VTK_BIQUADRATIC_QUAD (28), VTK_LAGRANGE_QUADRILATERAL (70) and
// VTK_BEZIER_QUADRILATERAL (77) of order (p, p) up to 10. Vertex and line cells (1, 2, 3, 4, 21,
// 35, 68, 75: boundary markers some writers add) are Skipped; anything else is Invalid and
// *problem says why, phrased to follow "cell N" (" has VTK cell type 10, which is not a supported
// surface cell (...)"). Point ids must lie in [0, num_points).
VtkCellResult add_vtk_cell(MeshInput &m, int64_t type, const int64_t *ids, int64_t n,
                           int64_t num_points, int64_t base, std::string *problem);

// What the readers say when a grid has none of them: "no surface cells (...)".
constexpr const char *kVtkSurfaceCells =
    "no surface cells (triangles VTK_TRIANGLE 5, VTK_QUADRATIC_TRIANGLE 22, "
    "VTK_LAGRANGE_TRIANGLE 69, VTK_BEZIER_TRIANGLE 76 or quadrilaterals VTK_QUAD 9, "
    "VTK_QUADRATIC_QUAD 23, VTK_BIQUADRATIC_QUAD 28, VTK_LAGRANGE_QUADRILATERAL 70, "
    "VTK_BEZIER_QUADRILATERAL 77)";

// The same without a MeshInput: an Added cell's nodes in canonical order into out[0 .. n) (room
// for kMaxVtkCellNodes; out must not overlap ids), its degree into *degree and its kind into
// *kind; out is not meaningful for a Skipped or Invalid cell.
VtkCellResult vtk_cell_nodes(int64_t type, const int64_t *ids, int64_t n, int64_t num_points,
                             int64_t base, int64_t *out, int *degree, CellKind *kind,
                             std::string *problem);

} // namespace hoct
