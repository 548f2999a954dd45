// The pieces of one mesh spread over the ranks of an MPI communicator, each rank holding its own
// (the pieces of a .pvtu it read, a parallel ParaView's piece, a Python rank's arrays), joined
// into the mesh join_pieces gives of all of them in rank order, each rank keeping its share
// (RankInput): the pieces' ghost cells and points dropped, the points the pieces share merged
// (by their global ids, or without ids by position) and numbered as the whole join numbers
// them, each point's span over the ranks, the whole's cell and triangle offsets and its
// fingerprint (passed from rank to rank). What crosses between ranks is the points the pieces
// may share, not the mesh (the whole, where needed: distributed/pieces_gather).
#pragma once

#include "distributed/distributed_tree.hpp"
#include "io/piece_join.hpp"
#include "io/read_limits.hpp"
#include "mesh/gll_nodes.hpp"

#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

namespace hoct {

struct RankRead {
  std::optional<RankInput> input; // on every rank, or on none
  // Why not (on every rank): the ranks could not be sure to join the pieces as join_pieces does
  // (a piece that cannot be read or joined, fields that differ, copies of a point at positions
  // that differ without ids): join the whole then, which reports what is wrong.
  std::string fallback;
  // How the ranks read it, where a user may want to know (empty: nothing to say).
  std::string note;
};

// Collective over `comm` (every rank calls it, with its own pieces, maybe none). `failure` not
// empty: this rank could not get its pieces (every rank then falls back). Never throws for the
// pieces' content. The input's read_whole is left for the caller to set.
RankRead join_rank_pieces(std::vector<FilePiece> pieces, const std::string &failure,
                          const std::string &source, const ReadLimits &limits, MPI_Comm comm);

// Collective over `comm`: DOLFINx's degree >= 3 nodes at GLL points resampled in each rank's
// share (resample_gll_cells: an edge's nodes get the same bits in every piece, as in the whole
// resampled at once) and in the whole that read_whole brings to rank 0. A rank's failure is
// every rank's (AgreedError). Returns the counts summed over the ranks.
GllResampling resample_gll_share(RankInput &input, MPI_Comm comm);

} // namespace hoct
