// Records or bytes sent between all ranks in one step (MPI_Alltoallv),
// every rank's bytes gathered on rank 0 (MPI_Gatherv) and rank 0's parts scattered to the ranks
// (MPI_Scatterv).
#pragma once

#include "util/error.hpp"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace hoct {

// Collective: sends out[r] to rank r (out is emptied) and returns what every rank sent here, in
// rank order. Throws hoct::Error where one step would carry 2 GiB or more to or from a rank.
template <class T>
std::vector<T> exchange_records(MPI_Comm comm, std::vector<std::vector<T>> &out) {
  static_assert(std::is_trivially_copyable_v<T>);
  const int ranks = static_cast<int>(out.size());
  std::vector<int> send_counts(out.size()), send_offsets(out.size()), receive_counts(out.size()),
      receive_offsets(out.size());
  std::vector<T> sending;
  for (int r = 0; r < ranks; ++r) {
    if ((sending.size() + out[r].size()) * sizeof(T) > static_cast<std::size_t>(INT_MAX))
      throw Error("a rank sends more than 2 GiB in one exchange: use more ranks");
    send_offsets[r] = static_cast<int>(sending.size() * sizeof(T));
    send_counts[r] = static_cast<int>(out[r].size() * sizeof(T));
    sending.insert(sending.end(), out[r].begin(), out[r].end());
    std::vector<T>().swap(out[r]);
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm);
  int64_t total = 0;
  for (int r = 0; r < ranks; ++r) {
    receive_offsets[r] = static_cast<int>(total);
    total += receive_counts[r];
  }
  if (total > INT_MAX)
    throw Error("a rank receives more than 2 GiB in one exchange: use more ranks");
  std::vector<T> received(static_cast<std::size_t>(total) / sizeof(T));
  MPI_Alltoallv(sending.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, received.data(),
                receive_counts.data(), receive_offsets.data(), MPI_BYTE, comm);
  return received;
}

// Collective: every rank's bytes on rank 0, in rank order (nothing elsewhere). Throws
// hoct::Error where rank 0 would receive 2 GiB or more.
inline std::vector<std::vector<std::byte>> gather_bytes(MPI_Comm comm,
                                                        std::span<const std::byte> own) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  int n = static_cast<int>(own.size());
  std::vector<int> sizes(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks));
  MPI_Gather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, comm);
  std::vector<std::byte> all;
  if (rank == 0) {
    int64_t total = 0;
    for (int r = 0; r < ranks; ++r) {
      offsets[r] = static_cast<int>(total);
      total += sizes[r];
    }
    if (total > INT_MAX)
      throw Error("the ranks' messages to rank 0 take 2 GiB or more: use fewer ranks per step");
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(own.data(), n, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0, comm);
  std::vector<std::vector<std::byte>> out;
  if (rank == 0)
    for (int r = 0; r < ranks; ++r)
      out.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + sizes[r]);
  return out;
}

// Collective: rank 0's parts[r] on rank r (parts is read on rank 0 only, one per rank). Throws
// hoct::Error on rank 0 where they take 2 GiB or more.
inline std::vector<std::byte> scatter_bytes(MPI_Comm comm,
                                            const std::vector<std::vector<std::byte>> &parts) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  std::vector<int> sizes(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks));
  std::vector<std::byte> all;
  if (rank == 0) {
    int64_t total = 0;
    for (int r = 0; r < ranks; ++r) {
      sizes[r] = static_cast<int>(parts[r].size());
      offsets[r] = static_cast<int>(std::min<int64_t>(total, INT_MAX));
      total += static_cast<int64_t>(parts[r].size());
    }
    if (total > INT_MAX)
      throw Error("rank 0's messages to the ranks take 2 GiB or more: use fewer ranks per step");
    for (const auto &p : parts)
      all.insert(all.end(), p.begin(), p.end());
  }
  int n = 0;
  MPI_Scatter(sizes.data(), 1, MPI_INT, &n, 1, MPI_INT, 0, comm);
  std::vector<std::byte> own(static_cast<std::size_t>(n));
  MPI_Scatterv(all.data(), sizes.data(), offsets.data(), MPI_BYTE, own.data(), n, MPI_BYTE, 0,
               comm);
  return own;
}

// Collective: sends out[r] to rank r (one per rank) and returns what every rank sent here, by
// rank. Throws hoct::Error where one step would carry 2 GiB or more to or from a rank.
inline std::vector<std::vector<std::byte>>
exchange_bytes(MPI_Comm comm, const std::vector<std::vector<std::byte>> &out) {
  const int ranks = static_cast<int>(out.size());
  std::vector<int> send_counts(out.size()), send_offsets(out.size()), receive_counts(out.size()),
      receive_offsets(out.size());
  std::vector<std::byte> sending;
  for (int r = 0; r < ranks; ++r) {
    if (sending.size() + out[r].size() > static_cast<std::size_t>(INT_MAX))
      throw Error("a rank sends more than 2 GiB in one exchange: use more ranks");
    send_offsets[r] = static_cast<int>(sending.size());
    send_counts[r] = static_cast<int>(out[r].size());
    sending.insert(sending.end(), out[r].begin(), out[r].end());
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm);
  int64_t total = 0;
  for (int r = 0; r < ranks; ++r) {
    receive_offsets[r] = static_cast<int>(std::min<int64_t>(total, INT_MAX));
    total += receive_counts[r];
  }
  if (total > INT_MAX)
    throw Error("a rank receives more than 2 GiB in one exchange: use more ranks");
  std::vector<std::byte> received(static_cast<std::size_t>(total));
  MPI_Alltoallv(sending.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, received.data(),
                receive_counts.data(), receive_offsets.data(), MPI_BYTE, comm);
  std::vector<std::vector<std::byte>> in;
  for (int r = 0; r < ranks; ++r)
    in.emplace_back(received.begin() + receive_offsets[r],
                    received.begin() + receive_offsets[r] + receive_counts[r]);
  return in;
}

// Collective: every rank's bytes on every rank, in rank order. Throws hoct::Error on every rank
// where they take 2 GiB or more.
inline std::vector<std::vector<std::byte>> all_gather_bytes(MPI_Comm comm,
                                                            std::span<const std::byte> own) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  int n = static_cast<int>(own.size());
  std::vector<int> sizes(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks));
  MPI_Allgather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm);
  int64_t total = 0;
  for (int r = 0; r < ranks; ++r) {
    offsets[r] = static_cast<int>(std::min<int64_t>(total, INT_MAX));
    total += sizes[r];
  }
  if (total > INT_MAX)
    throw Error("the ranks' messages take 2 GiB or more: use fewer ranks per step");
  std::vector<std::byte> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(own.data(), n, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, comm);
  std::vector<std::vector<std::byte>> out;
  for (int r = 0; r < ranks; ++r)
    out.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + sizes[r]);
  return out;
}

} // namespace hoct
