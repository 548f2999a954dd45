// Ridges and valleys along mesh edges: a constant edge where the gradient vanishes too (the
// field is c + w^2 q in the cell, w the barycentric coordinate that vanishes on the edge), as
// (x - 0.5)^2 on a mesh with a line of edges at x = 0.5, or a field symmetric about mesh edges.
// Where q keeps one strict sign on the whole cell, the cell lies on one side of the curve's
// value: the edge is a valley (q > 0) or a ridge (q < 0) as seen from the cell, its corners and
// points are one node (the edge's chain, contracted as a flat region), and its one sector in the
// cell reaches the cell's other edges at both corners, where those edges' chains connect it.
// With no other critical point in the cell (certified below), nothing else needs a path
// (docs/ALGORITHM.md §3, "Critical edges").
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <optional>

namespace hoct {

struct CriticalEdge {
  double value; // the edge's value c
  int side;     // +1: the cell lies above c (a valley), -1: below (a ridge)
  // The largest distance of the coefficients of the two rows next to the edge from c: the
  // stored field is c + w^2 q within it, on the whole cell.
  double slack;
};

// The local edge k of g (a constant edge) as a critical edge of this cell, if certified:
// - the two rows of coefficients nearest the edge within 2 `precision` (Field::precision) of c;
// - every other coefficient beyond 2 `precision` from c, all on one side: q, whose Bernstein
//   coefficients are theirs minus c times positive factors, keeps that sign;
// - no zero of grad g off the edge: grad g = w (2 q grad w + w grad q), and the second factor
//   dotted with grad w (a polynomial of degree d - 2) keeps one sign beyond rounding.
std::optional<CriticalEdge> critical_edge(const BernsteinTriangle &g, int k, double precision);

} // namespace hoct
