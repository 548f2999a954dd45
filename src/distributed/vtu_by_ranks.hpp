// One .vtu file read by every rank at once, each rank reading its own part of it alone
// (io/vtu_cell_range): rank r of R reads the file's cells [n r / R, n (r + 1) / R), the points
// they use and the r-th R-th of the points, which it checks and hashes. The ranks then make the
// RankInput distributed_tree needs, the one scatter_whole would send them from the whole: the
// points in the whole's order, each point's span over the ranks (only the ids in blocks of ids
// two ranks both use cross between them; for points numbered far from their cells, each rank
// gets its cells' points and their spans from the ranks that checked them), the whole's counts
// and its fingerprint (passed from rank to rank). No rank holds the whole.
#pragma once

#include "distributed/rank_join.hpp"
#include "io/field_selection.hpp"
#include "io/read_limits.hpp"

#include <mpi.h>

#include <string>

namespace hoct {

// Collective over `comm`. Never throws for the file's content: a file the ranks cannot read by
// parts (not one piece of raw appended arrays, ghost arrays, no surface cells) or that any part
// finds a problem in gives `fallback` on every rank (read it whole then, which reports what is
// wrong). The input's read_whole is set (rank 0 reads the file again).
RankRead read_vtu_by_ranks(const std::string &path, const FieldSelection &field,
                           const ReadLimits &limits, MPI_Comm comm);

} // namespace hoct
