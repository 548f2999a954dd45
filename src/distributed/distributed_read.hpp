// A partitioned file (.pvtu) read over MPI with each rank reading only its own pieces: rank r of
// R reads the pieces [r P / R, (r + 1) P / R) of the P the file lists, and the ranks join them
// (distributed/rank_join) into the mesh read_pvtu would give, each rank keeping its share.
#pragma once

#include "distributed/rank_join.hpp"
#include "io/field_selection.hpp"
#include "io/read_limits.hpp"

#include <mpi.h>

#include <string>

namespace hoct {

// Collective over `comm` (every rank calls it). Never throws for the file's content: a file
// the ranks cannot join alone gives `fallback` (read it whole then, which reports what is wrong).
RankRead read_pvtu_by_ranks(const std::string &path, const FieldSelection &field,
                            const ReadLimits &limits, MPI_Comm comm);

} // namespace hoct
