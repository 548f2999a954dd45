// Constant mesh edges that are pieces of a level set: the field is constant along the edge but
// its gradient is not zero there, so that in the cell the field strictly rises (or falls) from
// the edge into the cell. Such an edge holds no critical point as seen from that cell; its two
// vertices, of one value, are ordered by the total order on nodes (value, then id) as the ends
// of any edge, and the edge is one monotone piece of the edge chains (docs/ALGORITHM.md §2,
// "Level edges"). Dirichlet boundaries, symmetric data and fields of one coordinate on
// structured meshes have them by the thousand.
#pragma once

#include "poly/bernstein_triangle.hpp"

namespace hoct {

// True if the derivative of g (a cell's polynomial) along the inward normal of its local edge k
// (a constant edge) keeps a strict sign on the whole closed edge, certified on its Bernstein
// coefficients (subdivided where needed) with a margin: 6.4e4 eps times g's gradient
// coefficients (the level below which an edge node counts as critical:
// cell/sector_connections.hpp), and 2 d times `precision`, the data's (Field::precision).
// Decided per cell: the edge's other cell may fall back, or decide otherwise (a plateau's
// border), without changing what this cell's graph says.
bool is_level_edge(const BernsteinTriangle &g, int k, double precision);

// That margin: a derivative of g whose Bernstein coefficients are within it of zero may be zero
// (the rounding of g's gradient coefficients, and what the data's precision lets them move: a
// nearly constant cell's gradient is noise, of either sign).
double edge_derivative_margin(const BernsteinTriangle &g, double precision);

} // namespace hoct
