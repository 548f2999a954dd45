// The arcs of a tree computed over MPI drawn on the surface by the ranks' pieces (exact/
// piece_arcs): rank 0 broadcasts the arcs' ends and values; in each round, each rank draws the
// arcs whose ends it holds and joins within the round's values; for the others, each rank
// tells its neighbours the components of the nodes they share, reports its components and their
// touches to rank 0, which scatters the routes back as stretches, and gathers and joins the
// stretches drawn. No rank holds the whole graph.
#pragma once

#include "exact/piece_arcs.hpp"

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace hoct {

// How the arcs were drawn, and what rank 0 sent and received for them.
struct ArcPathCounts {
  int64_t arcs = 0;
  int64_t local = 0;                          // by a rank holding both ends
  int64_t routed[kArcRounds] = {};            // across ranks: within the values, below, above
  int64_t straight = 0;                       // no round found a route: drawn straight
  int64_t bytes_received = 0, bytes_sent = 0; // on rank 0
  int64_t component_bytes = 0; // of bytes_received: the components' reports (the rest: paths)
  int64_t neighbour_bytes =
      0; // the most a rank sent the others (rank 0 aside): shared keys, labels
  double seconds = 0;
};

// Collective: every rank passes its piece's graph (an empty one if it has no cells; its
// neighbours are set here), rank 0 the arcs (ignored elsewhere). On rank 0, each arc's path from
// its lower end to its upper end (empty where none was found: the caller draws it straight), and
// the counts; elsewhere nothing.
std::vector<std::vector<Vec3>> distributed_arc_paths(MPI_Comm comm, PieceArcGraph &piece,
                                                     std::vector<ArcEnds> arcs, int threads,
                                                     ArcPathCounts *counts = nullptr);

} // namespace hoct
