// A whole mesh read by rank 0 alone, cut into one share per rank and sent to each: every rank
// gets the RankInput distributed_tree(whole, ...) makes of the whole on every rank (its contiguous
// cells, their points' spans over the ranks, the whole's counts; the whole's fingerprint on rank
// 0), and only rank 0 ever holds the whole, while it cuts it. For a file the ranks cannot read
// by pieces or parts (.msh, a .vtu of inline arrays, ...): no rank but 0 reads it.
#pragma once

#include "distributed/distributed_tree.hpp"
#include "mesh/mesh_input.hpp"

#include <mpi.h>

namespace hoct {

// Collective over `comm`: `whole` is read on rank 0 only (the others pass null). Each share is
// formatted from the whole as it is sent, in blocks of 8 MiB: rank 0 holds the whole, the points'
// spans, a map of the whole's points and one block, never another rank's share. read_whole is
// left for the caller to set.
RankInput scatter_whole(const MeshInput *whole, MPI_Comm comm);

} // namespace hoct
