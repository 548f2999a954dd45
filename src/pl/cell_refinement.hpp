// The k x k refinement of ONE reference triangle into linear sub-triangles, with optional extra
// points on its three edges, described abstractly so that callers can give the sub-vertices
// global ids: corners by corner index, edge points by (local edge, lattice step or extra index),
// interior points by position. Used by the mesh refinement (pl/refinement.hpp) and by the
// degenerate-cell fallback of the exact tree.
#pragma once

#include <array>
#include <vector>

namespace hoct {

struct CellSubVertex {
  enum class Kind { Corner, EdgeLattice, EdgeExtra, Interior };
  Kind kind;
  int corner = -1;     // Corner: 0, 1, 2
  int edge = -1;       // EdgeLattice / EdgeExtra: local edge 0, 1, 2
  int index = -1;      // EdgeLattice: step s (1..k-1) from the edge's first corner;
                       // EdgeExtra: index into that edge's extra points
  double u = 0, v = 0; // position in the reference triangle
};

struct CellRefinement {
  std::vector<CellSubVertex> vertices;
  std::vector<std::array<int, 3>> triangles; // counter-clockwise in (u, v)
};

// extra[k]: parameters s in (0, 1) along local edge k from corner k, ascending, none equal to a
// lattice parameter j/k (callers filter those).
CellRefinement refine_cell(int k, const std::array<std::vector<double>, 3> &extra);

} // namespace hoct
