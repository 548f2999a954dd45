// Node orderings of Lagrange triangles in file formats, as permutations of the canonical lattice
// order (poly/lattice.hpp).
//
// VTK_LAGRANGE_TRIANGLE (69), VTK_TRIANGLE (5), VTK_QUADRATIC_TRIANGLE (22) and Gmsh's complete
// triangles (types 2, 9, 21, 23, 25, 42, 43, 44, 45, 46) all order nodes recursively: the three
// corners, then the interior nodes of edge 0->1, 1->2, 2->0 (each from its first corner), then the
// interior nodes as a triangle of degree d-3 ordered the same way. Both are kept as named orderings
// so that a future difference has one place to go; tests check each against its own tool.
#pragma once

#include <vector>

namespace hoct {

enum class NodeOrdering { Vtk, Gmsh };

// perm[file_position] = canonical lattice index, for a degree-d triangle (d >= 1).
const std::vector<int> &node_order_to_lattice(NodeOrdering ordering, int degree);

// perm[file_position] = canonical tensor index i + (p+1) j (node at (i/p, j/p),
// mesh/mesh_input.hpp) for a complete quadrilateral of bidegree (p, p) (p >= 1). VTK
// (VTK_LAGRANGE_QUADRILATERAL 70, VTK_BEZIER_QUADRILATERAL 77, and VTK_QUAD 9 and
// VTK_BIQUADRATIC_QUAD 28 as its orders 1 and 2): corners (0,0) (1,0) (1,1) (0,1), then the edge
// nodes of (0,0)->(1,0), (1,0)->(1,1), (0,1)->(1,1), (0,0)->(0,1) (edges along increasing s or t),
// then the interior, s fastest. Gmsh (complete quadrangles, types 3, 10, 36, 37, 38, 47, 48, 49,
// 50, 51): corners, then the edges 0->1, 1->2, 2->3, 3->0, each from its first corner, then the
// interior as a quadrangle of order p - 2 ordered the same way.
const std::vector<int> &quad_node_order_to_tensor(NodeOrdering ordering, int p);

// The same for a serendipity quadrilateral of order p >= 2 (boundary nodes only, VTK order:
// VTK_QUADRATIC_QUAD 23; Gmsh order: its incomplete quadrangles), into the canonical position
// among the boundary nodes (poly/quad_basis.hpp: quad_boundary_indices).
const std::vector<int> &serendipity_node_order(NodeOrdering ordering, int p);

// Degree of a complete triangle with n nodes, or -1 if n is not (d+1)(d+2)/2 for some d >= 1.
int degree_from_node_count(long long n);

} // namespace hoct
