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

// Degree of a complete triangle with n nodes, or -1 if n is not (d+1)(d+2)/2 for some d >= 1.
int degree_from_node_count(long long n);

} // namespace hoct
