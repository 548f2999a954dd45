#include "distributed/fingerprint_chain.hpp"

#include <type_traits>

namespace hoct {

uint64_t fingerprint_by_ranks(MPI_Comm comm, const std::array<int64_t, 4> &counts, bool with_kinds,
                              const std::function<void(int, FingerprintState &)> &own) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  static_assert(std::is_trivially_copyable_v<FingerprintState>);
  constexpr int kStateBytes = static_cast<int>(sizeof(FingerprintState));
  constexpr int kTag = 77;
  FingerprintState fp = fingerprint_start();
  const int sections = with_kinds ? 5 : 4;
  for (int s = 0; s < sections; ++s) {
    if (rank > 0)
      MPI_Recv(&fp, kStateBytes, MPI_BYTE, rank - 1, kTag, comm, MPI_STATUS_IGNORE);
    else if (s > 0 && ranks > 1)
      MPI_Recv(&fp, kStateBytes, MPI_BYTE, ranks - 1, kTag, comm, MPI_STATUS_IGNORE);
    if (rank == 0 && s < 4)
      fingerprint_count(fp, static_cast<uint64_t>(counts[static_cast<std::size_t>(s)]));
    own(s, fp);
    if ((s == kDegreesSection || s == kKindsSection) && rank == ranks - 1)
      fingerprint_flush_packed(fp);
    if (rank < ranks - 1)
      MPI_Send(&fp, kStateBytes, MPI_BYTE, rank + 1, kTag, comm);
    else if (s + 1 < sections && ranks > 1)
      MPI_Send(&fp, kStateBytes, MPI_BYTE, 0, kTag, comm);
  }
  if (ranks > 1) // the end state from the last rank
    MPI_Bcast(&fp, kStateBytes, MPI_BYTE, ranks - 1, comm);
  return fingerprint_value(fp);
}

void fingerprint_cell_bytes(FingerprintState &state, std::span<const uint8_t> bytes,
                            std::size_t cells) {
  fingerprint_packed(state, bytes.data(), bytes.size());
  const std::vector<uint8_t> zeros(cells - bytes.size(), 0);
  fingerprint_packed(state, zeros.data(), zeros.size());
}

int64_t exclusive_sum(MPI_Comm comm, int64_t own) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int64_t before = 0;
  MPI_Exscan(&own, &before, 1, MPI_INT64_T, MPI_SUM, comm);
  return rank == 0 ? 0 : before;
}

} // namespace hoct
