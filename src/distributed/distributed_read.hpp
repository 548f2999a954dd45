// A partitioned file (.pvtu) read over MPI with each rank reading only its own pieces: rank r of
// R reads the pieces [r P / R, (r + 1) P / R) of the P the file lists, and the ranks join them
// together into the mesh read_pvtu would give, each rank keeping its share (RankInput): the
// pieces' ghost cells and points dropped, the points the pieces share merged (by their global
// ids, or without ids by position) and numbered as the whole join numbers them, each point's
// span over the ranks, the whole's cell and triangle offsets and its fingerprint (passed from
// rank to rank). What crosses between ranks is the points the pieces may share, not the mesh.
#pragma once

#include "distributed/distributed_tree.hpp"
#include "io/field_selection.hpp"
#include "io/read_limits.hpp"

#include <mpi.h>

#include <optional>
#include <string>

namespace hoct {

struct RankRead {
  std::optional<RankInput> input; // on every rank, or on none
  // Why not (on every rank): the ranks could not be sure to join the pieces as read_pvtu does
  // (a piece that cannot be read or joined, fields that differ, copies of a point at positions
  // that differ without ids): read the whole file then, which reports what is wrong.
  std::string fallback;
};

// Collective over `comm` (every rank calls it). Never throws for the file's content: a file
// the ranks cannot join alone gives `fallback`.
RankRead read_pvtu_by_ranks(const std::string &path, const FieldSelection &field,
                            const ReadLimits &limits, MPI_Comm comm);

} // namespace hoct
