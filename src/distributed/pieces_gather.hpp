// Every rank's pieces of one mesh (FilePiece: cells, points, values, ghost flags, global ids)
// sent as bytes to rank 0 or to every rank and joined there by io/piece_join's join_pieces, in
// rank order: the whole mesh where a report or a fallback needs it (distributed/rank_join gives
// each rank its share without it).
#pragma once

#include "io/piece_join.hpp"
#include "mesh/mesh_input.hpp"

#include <mpi.h>

#include <string>
#include <vector>

namespace hoct {

// Collective over `comm`: every rank's pieces to rank 0, joined there by join_pieces (in rank
// order; its errors thrown on rank 0). The other ranks get an empty mesh.
MeshInput join_pieces_on_root(const std::vector<FilePiece> &pieces, const std::string &where,
                              int threads, MPI_Comm comm);

// Collective over `comm`: every rank's pieces on every rank, joined there by join_pieces (the same
// mesh, or the same InputError, on every rank).
MeshInput join_pieces_everywhere(const std::vector<FilePiece> &pieces, const std::string &where,
                                 int threads, MPI_Comm comm);

} // namespace hoct
