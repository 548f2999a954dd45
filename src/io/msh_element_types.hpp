// Gmsh element types (the "elementType" numbers of MSH files): name, dimension, order and node
// count, as gmsh.model.mesh.getElementProperties reports them in Gmsh 4.8. The MSH reader uses
// the table to read complete triangles, skip points and lines, and name anything else it rejects.
#pragma once

#include "mesh/mesh_input.hpp"

namespace hoct {

struct MshElementType {
  int type;
  const char *name; // Gmsh's name, e.g. "Triangle 10", "Quadrilateral 4"
  int dimension;
  int order;
  int nodes;
  // Degree d of a complete Lagrange triangle ((d+1)(d+2)/2 nodes), 0 for any other type.
  int complete_triangle_degree() const;
  // Triangles with fewer nodes than the complete one of their order (serendipity, "Triangle 9").
  bool incomplete_triangle() const;
  // The order of a surface cell hoct reads (a complete triangle, a complete quadrangle, an
  // incomplete quadrangle of order >= 2 with its 4p boundary nodes), 0 for any other type; and
  // its kind (LagrangeTriangle, LagrangeQuadrilateral, SerendipityQuadrilateral).
  int surface_degree() const;
  CellKind surface_kind() const;
};

// nullptr for a type Gmsh does not define or whose node count is not fixed (polygons, XFEM).
const MshElementType *msh_element_type(int type);

} // namespace hoct
