// A mesh cut into pieces of contiguous input cells (piece r of n: cells [r N / n, (r + 1) N / n)),
// each piece a mesh input of its own, for a distributed tree (one piece per MPI rank) and for
// the tests that check a partitioned tree against the whole one.
#pragma once

#include "mesh/mesh_input.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// The input cells [begin, end) of piece `piece` of `pieces`.
std::array<int64_t, 2> piece_cell_range(int64_t cells, int pieces, int piece);

struct MeshPiece {
  // The piece's cells, in the whole's order, and the points they use, in ascending order of
  // their indices in the whole (so that the piece numbers its vertices, edges and cells in the
  // whole's order).
  MeshInput input;
  std::vector<int64_t> global_point; // per point of the piece, its index in the whole
  int64_t first_cell = 0;            // the whole's index of the piece's first cell
  // Per point of the piece, the lowest and highest piece whose cells use it (filled by
  // partition_piece: point_piece_spans of its points).
  std::vector<std::array<int32_t, 2>> point_span;
};

// Input cells [begin, end) of `whole` as a piece.
MeshPiece extract_piece(const MeshInput &whole, int64_t begin, int64_t end);
// Piece `piece` of `pieces` (piece_cell_range) with its points' spans: one pass over the other
// pieces' cells, the whole's points never indexed by a whole-sized array of spans.
MeshPiece partition_piece(const MeshInput &whole, int pieces, int piece);

// Per point of `whole`, the lowest and the highest piece of `pieces` whose cells use it
// ({-1, -1} for a point no cell uses).
std::vector<std::array<int32_t, 2>> point_piece_spans(const MeshInput &whole, int pieces);

// The spans of a piece's points (`global_point`: their indices in the whole), from the whole's.
std::vector<std::array<int32_t, 2>>
piece_point_spans(std::span<const int64_t> global_point,
                  std::span<const std::array<int32_t, 2>> whole_spans);

// Triangles the mesh build makes of each input cell (1, or 2 for a quadrilateral), summed over
// the input cells [0, end): the whole mesh's id of a piece's first triangle.
int64_t triangles_before(const MeshInput &whole, int64_t end);

} // namespace hoct
