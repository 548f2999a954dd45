// The triangular lattice of multi-indices (i, j, k), i + j + k = d, that indexes both Bernstein
// coefficients and equispaced Lagrange nodes of a degree-d triangle.
//
// Reference triangle: P0 = (0,0), P1 = (1,0), P2 = (0,1); a point (u, v) has barycentric
// coordinates (1-u-v, u, v). Lattice point (a, b) with a, b >= 0, a + b <= d is the multi-index
// (d-a-b, a, b), located at (u, v) = (a/d, b/d).
//
// Canonical order: by b, then a: index(a, b) = b(d+1) - b(b-1)/2 + a. The three corners are NOT
// first in this order; node orderings of file formats are permutations of it
// (poly/lagrange_node_order.hpp).
#pragma once

#include <array>

namespace hoct {

constexpr int lattice_size(int d) { return (d + 1) * (d + 2) / 2; }

constexpr int lattice_index(int d, int a, int b) { return b * (d + 1) - b * (b - 1) / 2 + a; }

// Canonical index of corner k (0: (0,0), 1: (d,0), 2: (0,d)).
constexpr int corner_index(int d, int k) { return k == 0 ? 0 : (k == 1 ? d : lattice_size(d) - 1); }

// Canonical index of the t-th lattice point along local edge k (0: corner 0 -> 1, 1: corner
// 1 -> 2, 2: corner 2 -> 0), t = 0..d.
constexpr int edge_lattice_index(int d, int k, int t) {
  return k == 0 ? lattice_index(d, t, 0)
                : (k == 1 ? lattice_index(d, d - t, t) : lattice_index(d, 0, d - t));
}

// (a, b) of a canonical index, for degree d.
std::array<int, 2> lattice_point(int d, int index);

} // namespace hoct
