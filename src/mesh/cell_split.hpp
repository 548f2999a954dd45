// Quadrilaterals and Bezier cells as Lagrange triangles carrying exactly the same polynomials,
// so that everything after it (topology, field, geometry, the exact and refined trees) sees one
// kind of cell (docs/ALGORITHM.md §1.3).
//
// - A quadrilateral of bidegree (p, p) (Lagrange, serendipity or Bezier) is cut along one of its
//   diagonals into two triangles. On each, the field and the geometry map, restricted, are
//   polynomials of total degree 2p in the triangle's coordinates: the triangles are Lagrange
//   triangles of degree 2p whose nodes are the quadrilateral's values at its half-step grid
//   (k/2p, l/2p). The nodes the quadrilateral has keep their points; the others are new points.
//   Points on a quadrilateral's edge are computed from that edge's nodes alone, in the direction
//   of increasing point id: both cells of an edge compute them bit for bit alike. The diagonal is
//   the one along which the field varies most (a diagonal on which the field is constant would be
//   a degenerate edge).
// - A Bezier triangle becomes the Lagrange triangle of its polynomial: its nodes' values and
//   positions are its values at its lattice points (each point evaluated once).
// Values are interpolated relative to the data's reference value (mesh/field.hpp), so a field
// far from zero loses nothing to the shift.
#pragma once

#include "mesh/mesh_input.hpp"
#include "mesh/problem_log.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

// A point of a cell: the cell and its parametric position (reference triangle (u, v), or unit
// square (s, t) for a quadrilateral).
struct CellPlace {
  int64_t cell = -1;
  std::array<double, 2> uv{0, 0};
};

// Where each cell of the split mesh comes from.
class CellOrigins {
public:
  // True when the mesh cells are the input cells (no quadrilateral): every map is the identity.
  bool identity() const { return input_cell_.empty(); }
  int64_t input_cell(int64_t mesh_cell) const {
    return identity() ? mesh_cell : input_cell_[static_cast<std::size_t>(mesh_cell)];
  }
  // A point of a mesh cell as a point of its input cell.
  CellPlace to_input(int64_t mesh_cell, std::array<double, 2> uv) const;
  // A point of an input cell as a point of the mesh cell holding it (cell -1 for an input cell
  // that does not exist).
  CellPlace to_mesh(int64_t input_cell, std::array<double, 2> uv) const;
  int64_t num_input_cells() const { return static_cast<int64_t>(first_.size()) - 1; }
  // The number of input cells, given the mesh's cell count (the same when identity()).
  int64_t num_input_cells(int64_t mesh_cells) const {
    return identity() ? mesh_cells : num_input_cells();
  }
  // An input cell that became two triangles (a quadrilateral: its points are (s, t) in [0,1]^2).
  bool quadrilateral(int64_t input_cell) const {
    return !identity() && first_[static_cast<std::size_t>(input_cell) + 1] -
                                  first_[static_cast<std::size_t>(input_cell)] ==
                              2;
  }

  // Parts: the triangle itself, or the two halves of a quadrilateral cut along (0,0)-(1,1)
  // (corners 0 1 2 and 0 2 3) or along (1,0)-(0,1) (corners 0 1 3 and 1 2 3).
  enum Part : uint8_t { Whole = 0, Diagonal02Low, Diagonal02High, Diagonal13Low, Diagonal13High };
  void add(int64_t input_cell, Part part);
  void close(int64_t num_input_cells); // after the last add

private:
  std::vector<int64_t> input_cell_;
  std::vector<uint8_t> part_;
  std::vector<int64_t> first_{0}; // first mesh cell of each input cell, and the end
};

struct SplitCells {
  MeshInput mesh; // Lagrange triangles only
  CellOrigins origins;
  int64_t quadrilaterals = 0, bezier_cells = 0;
};

// Needs an input whose cells passed check_input. Records in `problems` a Bezier cell's control
// point that a Lagrange cell also uses as a node (the two cannot agree). `threads` split the
// quadrilaterals in parallel (the result does not depend on their number).
SplitCells split_cells(const MeshInput &input, ProblemLog &problems, int threads = 1);

// Every cell as a Lagrange cell of its own shape and degree, its nodes on the surface (for the
// piecewise-linear reading of the nodes): Bezier cells' control points replaced by their values
// and positions at the nodes' places, serendipity cells given their interior nodes (new points).
MeshInput nodal_cells(const MeshInput &input, ProblemLog &problems);

} // namespace hoct
