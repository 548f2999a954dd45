// The combinatorial skeleton of a triangle mesh: global vertices (the cells' corner nodes),
// global edges keyed by their vertex pair, each cell's edges with their orientation, edge-cell
// incidence, and the surface's invariants (Euler characteristic, boundary loops, components).
//
// Local edge k of a cell runs from its corner k to corner (k+1) mod 3. A global edge is stored as
// (lo, hi) with lo < hi by vertex id; `edge_reversed(c, k)` says the cell runs it from hi to lo.
#pragma once

#include "mesh/mesh_input.hpp"
#include "mesh/problem_log.hpp"
#include "util/uninitialized_vector.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace hoct {

class Topology {
public:
  // Builds the skeleton; records non-manifold edges and vertices, repeated corners and
  // inconsistent orientation in `problems`. Cells must reference valid point indices.
  // `threads`: most passes run in parallel; the result and the report do not depend on it.
  // `open_points` (empty, or a flag per point): points where the surface may go on beyond this
  // input (a piece's points shared with other pieces, mesh/piece_surface.hpp); their fans are
  // not checked (no pinch, no second fan reported there), as the input holds only part of them.
  static Topology build(const MeshInput &input, ProblemLog &problems, int threads = 1,
                        std::span<const uint8_t> open_points = {});

  // This topology cut open along the interior edges e with is_cut[e] (mesh/cut_surface.hpp):
  // vertex v becomes vertices first[v] .. first[v + 1] - 1 (the copies numbered in the order of
  // the originals, vertex i its own point i), its corners the first of them except the corners
  // (3 c + k, vertex) listed, ascending, in `split_corners`; each cut edge one boundary edge per
  // side. The same as build() of those corners would give, derived from this one without sorting
  // the edges again (src/mesh/topology_cut.cpp). The components are this one's (the caller cuts
  // no component apart); Euler characteristic and boundary loops are counted. `edge_origin`, if
  // given, receives per edge of the cut the edge of this topology it copies. Throws
  // std::logic_error where the numbering would reverse an edge or a cut edge is not interior.
  Topology cut_open(std::span<const int64_t> first,
                    std::span<const std::pair<int64_t, int64_t>> split_corners,
                    std::span<const uint8_t> is_cut,
                    std::vector<int64_t> *edge_origin = nullptr) const;

  int64_t num_vertices() const { return static_cast<int64_t>(vertex_point_.size()); }
  int64_t num_edges() const { return static_cast<int64_t>(edge_vertices_.size()); }
  int64_t num_cells() const { return static_cast<int64_t>(cell_vertices_.size()); }

  int64_t vertex_point(int64_t v) const { return vertex_point_[v]; }
  // The lowest-id cell at vertex v, and which of its corners v is.
  int64_t vertex_cell(int64_t v) const { return vertex_cell_[v]; }
  int vertex_corner(int64_t v) const { return vertex_corner_[v]; }
  const std::array<int64_t, 3> &cell_vertices(int64_t c) const { return cell_vertices_[c]; }
  const std::array<int64_t, 2> &edge_vertices(int64_t e) const { return edge_vertices_[e]; }
  // Every edge's (lo, hi), by edge id.
  std::span<const std::array<int64_t, 2>> all_edge_vertices() const { return edge_vertices_; }
  int64_t cell_edge(int64_t c, int k) const { return cell_edges_[c][k]; }
  bool edge_reversed(int64_t c, int k) const { return (cell_edge_reversed_[c] >> k) & 1u; }
  // The local index (0, 1, 2) of edge e in cell c, or -1 if c does not have it.
  int local_edge(int64_t c, int64_t e) const {
    for (int k = 0; k < 3; ++k)
      if (cell_edges_[c][k] == e)
        return k;
    return -1;
  }

  // Cells incident to edge e (1 on the boundary, 2 inside, more if non-manifold), ascending.
  const int64_t *edge_cells_begin(int64_t e) const { return &edge_cells_[edge_cell_offset_[e]]; }
  int edge_cell_count(int64_t e) const {
    return static_cast<int>(edge_cell_offset_[e + 1] - edge_cell_offset_[e]);
  }
  // The cell across local edge k of cell c, or -1 on the boundary (or a non-manifold edge).
  int64_t neighbor(int64_t c, int k) const;
  bool is_boundary_edge(int64_t e) const { return edge_cell_count(e) == 1; }

  int64_t euler_characteristic() const { return num_vertices() - num_edges() + num_cells(); }
  int64_t boundary_loops() const { return boundary_loops_; }
  int64_t boundary_edges() const { return boundary_edges_; }
  int64_t components() const { return components_; }
  bool orientable() const { return orientable_; }
  // +1 or -1 per cell: a consistent orientation of each component (the first cell of each
  // component keeps its own). Meaningless where !orientable().
  int8_t cell_parity(int64_t c) const { return cell_parity_[c]; }

private:
  // Sized, then filled completely by parallel passes (their pages first touched by those).
  UninitializedVector<int64_t> vertex_point_, vertex_cell_;
  UninitializedVector<int8_t> vertex_corner_;
  UninitializedVector<std::array<int64_t, 3>> cell_vertices_;
  UninitializedVector<std::array<int64_t, 2>> edge_vertices_;
  UninitializedVector<std::array<int64_t, 3>> cell_edges_;
  UninitializedVector<uint8_t> cell_edge_reversed_;
  UninitializedVector<int64_t> edge_cell_offset_, edge_cells_;
  UninitializedVector<int8_t> cell_parity_;
  int64_t boundary_loops_ = 0, boundary_edges_ = 0, components_ = 0;
  bool orientable_ = true;
};

} // namespace hoct
