// The arcs of a tree computed over MPI drawn on the surface by the ranks' pieces
// (exact/piece_arc_rounds over MPI: the ranks' shared keys and labels by MPI_Alltoallv, the
// reports and paths gathered on rank 0, the stretches scattered from it). No rank holds the
// whole graph.
#pragma once

#include "exact/piece_arc_rounds.hpp"

#include <mpi.h>

#include <vector>

namespace hoct {

// Collective: every rank passes its piece's graph (an empty one if it has no cells; its number
// and neighbours are set here), rank 0 the arcs (ignored elsewhere). On rank 0, each arc's path
// from its lower end to its upper end (empty where none was found: the caller draws it
// straight), and the counts; elsewhere nothing.
std::vector<std::vector<Vec3>> distributed_arc_paths(MPI_Comm comm, PieceArcGraph &piece,
                                                     std::vector<ArcEnds> arcs, int threads,
                                                     ArcPathCounts *counts = nullptr);

} // namespace hoct
