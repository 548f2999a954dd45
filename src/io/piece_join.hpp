// The pieces of a partitioned output (a .pvtu's, the parts of a .pvd's step) joined into one
// mesh: each piece's ghost cells dropped, and the points the pieces share merged.
#pragma once

#include "io/vtu_reader.hpp"
#include "mesh/mesh_input.hpp"

#include <string>
#include <vector>

namespace hoct {

struct FilePiece {
  MeshInput input;
  VtuPieceArrays arrays; // its ghost levels and global ids (none for a part joined already)
  std::string file;      // the piece's file, for messages
};

// One mesh of the pieces, consumed piece by piece. Of each piece, the cells with vtkGhostType's
// DUPLICATECELL bit are dropped (another piece owns them), then the points no kept cell uses
// that are ghost points (DUPLICATEPOINT) or were used by ghost cells only. The points the pieces
// share are merged: by global id when `by_ids` and every piece has ids (their positions must
// agree), else by position (within 1e-9 of the bounding-box diagonal, a point with the points of
// other pieces only: a crack inside a piece stays one). Merged points must have the same value
// (within 1e-9 of the largest magnitude). Every piece must have the same field. Throws
// InputError "<where>: ..." naming the piece files for anything else. Empty pieces (an idle
// rank's) are skipped; no cell at all is an error.
MeshInput join_pieces(std::vector<FilePiece> pieces, const std::string &where, bool by_ids,
                      int threads = 1);

// The first half of join_pieces: each piece's kept cells and points (ghosts dropped), piece
// after piece, not merged (each piece consumed). For a distributed join of some of the pieces
// (distributed/distributed_read).
struct PieceParts {
  MeshInput mesh;                 // the kept points in piece order, the cells referring to them
  std::vector<uint32_t> piece_of; // each point's piece (index into the pieces given)
  std::vector<int64_t> global;    // each point's global id, when merging by ids
  bool ids = false;               // by_ids and every non-empty piece has ids
  std::size_t filled = 0;         // pieces that are not empty
};
PieceParts concatenate_pieces(std::vector<FilePiece> &pieces, const std::string &where,
                              bool by_ids);

} // namespace hoct
