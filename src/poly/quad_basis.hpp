// The one-dimensional factors of tensor-product polynomials on the unit square, as the split of
// a quadrilateral of bidegree (p, p) into two triangles of degree 2p needs them
// (mesh/cell_split): the basis at the half-step grid k / (2p), and the serendipity interpolant.
#pragma once

#include <vector>

namespace hoct {

// Largest bidegree p of a quadrilateral: its triangles have degree 2p <= kMaxDegree.
constexpr int kMaxQuadDegree = 10;

// E[k (p+1) + i] = L_i(k / (2p)), k = 0..2p, i = 0..p: the Lagrange basis of the equispaced nodes
// i / p at the half-step grid. Rows of even k are exactly the unit vectors (the nodes
// themselves). Computed in long double, cached; p in [1, kMaxQuadDegree].
const std::vector<double> &lagrange_at_half_steps(int p);

// The same for the Bernstein basis B_i^p (Bezier cells): E[k (p+1) + i] = B_i^p(k / (2p)).
const std::vector<double> &bernstein_at_half_steps(int p);

// Serendipity quadrilaterals of order p (2 <= p <= kMaxQuadDegree): nodes on the boundary only,
// 4p of them, and the space of monomials s^i t^j with max(i, j) <= p and min(i, j) <= 1 (the
// 8-node VTK_QUADRATIC_QUAD and Gmsh's incomplete quadrangles). S[r * 4p + b] gives the r-th
// interior node's value (interior nodes (i, j), 0 < i, j < p, in tensor order) from the boundary
// node values (boundary nodes in tensor order i + (p+1) j). Cached.
const std::vector<double> &serendipity_interior(int p);

// Tensor indices (i + (p+1) j) of the boundary nodes of bidegree p, ascending: the canonical node
// order of a serendipity quadrilateral in MeshInput.
std::vector<int> quad_boundary_indices(int p);

} // namespace hoct
