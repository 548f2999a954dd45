// Constant mesh edges where the gradient vanishes: along the whole edge (a ridge or valley lying
// on mesh edges, as (x - 0.5)^2 on a mesh with a line of edges at x = 0.5, or data symmetric
// about mesh edges), or only at its ends (a Dirichlet side meeting another at a corner of the
// domain, where the gradient vanishes). In both, with w the barycentric coordinate that vanishes
// on the edge, the derivative D = grad g . grad w (grad w points into the cell) vanishes there
// and, certified below, nowhere else in the cell: g rises (or falls) from the edge over the
// whole cell, which then lies on one side of the edge's value c and holds no other critical
// point. The edge's critical points (the whole edge, or its critical ends) have a single sector
// in the cell, which reaches its other two edges at the edge's corners, where their chains
// connect it; nothing needs a path but the other edges' nodes (docs/ALGORITHM.md §3, "Critical
// edges").
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <optional>

namespace hoct {

struct CriticalEdge {
  double value; // the edge's value c
  int side;     // +1: the cell lies above c (a valley, a minimum), -1: below
  bool curve;   // the whole edge is critical (else only the ends in `ends`)
  // Bit 0: the edge's first corner (corner k) is critical, bit 1: its second (corner k + 1).
  unsigned ends;
  // How far the stored field may be from the certified model (c + w^2 q on a critical edge:
  // the largest distance of the two rows next to the edge from c; at a critical end the
  // rounding of D there).
  double slack;
};

// The local edge k of g (a constant edge) as a critical edge of this cell, if certified:
// - a whole critical edge: the two rows of coefficients nearest the edge within 2 `precision`
//   (Field::precision) of c; every other coefficient beyond that from c, all on one side (g =
//   c + w^2 q, q's Bernstein coefficients theirs minus c times positive factors, so q keeps
//   that sign); and D / w = 2 q |grad w|^2 + w grad q . grad w of one sign on its coefficients;
// - critical ends: every Bernstein coefficient of D of one strict sign beyond a margin (6.4e4
//   eps of g's gradient coefficients and 2 d `precision`), except those at the edge's corners,
//   which may be within that margin of zero (the critical ends). D >= 0 with zeros only at
//   those corners: g rises from the edge along grad w everywhere else.
std::optional<CriticalEdge> critical_edge(const BernsteinTriangle &g, int k, double precision);

} // namespace hoct
