// The whole input's fingerprint (mesh/mesh_fingerprint's sections, in its order) hashed from rank
// to rank when each rank holds a consecutive part of every section: rank 0 starts each section
// with its count, each rank hashes its own part and passes the running state on, the last rank
// ends the packed sections (degrees, kinds). Serial over the ranks, about 1 ns per 8-byte word.
#pragma once

#include "mesh/mesh_fingerprint.hpp"

#include <mpi.h>

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace hoct {

enum FingerprintSection {
  kPointsSection,
  kValuesSection,
  kDegreesSection,
  kNodesSection,
  kKindsSection
};

// Collective. `counts`: the whole's points, values, cells and cell nodes; `with_kinds`: the kinds
// section too (a whole of cells other than Lagrange triangles); `own(section, state)` hashes
// this rank's part of the section into the state. Every rank gets the value.
uint64_t fingerprint_by_ranks(MPI_Comm comm, const std::array<int64_t, 4> &counts, bool with_kinds,
                              const std::function<void(int, FingerprintState &)> &own);

// One byte per cell (degrees, kinds) for `cells` cells: `bytes`, then zeros for the cells it
// lacks (a rank of triangles alone keeps no kinds: theirs are zeros, Lagrange triangles).
void fingerprint_cell_bytes(FingerprintState &state, std::span<const uint8_t> bytes,
                            std::size_t cells);

// Collective: the sum of `own` over the ranks before this one (0 on rank 0).
int64_t exclusive_sum(MPI_Comm comm, int64_t own);

} // namespace hoct
