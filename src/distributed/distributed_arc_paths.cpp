#include "distributed/distributed_arc_paths.hpp"

#include "distributed/mpi_exchange.hpp"

#include <algorithm>
#include <type_traits>

namespace hoct {
namespace {

// Collective: rank 0's array on every rank.
template <class T> void broadcast_array(MPI_Comm comm, std::vector<T> &v) {
  static_assert(std::is_trivially_copyable_v<T>);
  uint64_t n = v.size();
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, comm);
  v.resize(n);
  const std::size_t bytes = n * sizeof(T);
  for (std::size_t at = 0; at < bytes; at += std::size_t{1} << 30)
    MPI_Bcast(reinterpret_cast<std::byte *>(v.data()) + at,
              static_cast<int>(std::min(bytes - at, std::size_t{1} << 30)), MPI_BYTE, 0, comm);
}

// One piece per rank.
class MpiLinks final : public PieceLinks {
public:
  explicit MpiLinks(MPI_Comm comm) : comm_(comm) {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &ranks_);
  }
  int pieces() const override { return ranks_; }
  bool root() const override { return rank_ == 0; }
  std::vector<std::vector<Bytes>> exchange(std::vector<std::vector<Bytes>> out) override {
    return {exchange_bytes(comm_, out.at(0))};
  }
  std::vector<Bytes> gather(std::vector<Bytes> own) override {
    return gather_bytes(comm_, own.at(0));
  }
  std::vector<Bytes> scatter(std::vector<Bytes> parts) override {
    return {scatter_bytes(comm_, parts)};
  }
  std::vector<int32_t> least(std::vector<std::vector<int32_t>> own) override {
    std::vector<int32_t> v = std::move(own.at(0));
    MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_INT32_T, MPI_MIN, comm_);
    return v;
  }
  void broadcast(std::vector<int64_t> &list) override { broadcast_array(comm_, list); }
  int64_t largest(int64_t own) override {
    int64_t m = 0;
    MPI_Reduce(&own, &m, 1, MPI_INT64_T, MPI_MAX, 0, comm_);
    return m;
  }

private:
  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
};

} // namespace

std::vector<std::vector<Vec3>> distributed_arc_paths(MPI_Comm comm, PieceArcGraph &piece,
                                                     std::vector<ArcEnds> arcs, int threads,
                                                     ArcPathCounts *counts) {
  MpiLinks links(comm);
  broadcast_array(comm, arcs);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  piece.piece = rank;
  PieceArcGraph *local[1] = {&piece};
  ArcPathCounts c;
  std::vector<std::vector<Vec3>> paths = draw_arcs_by_pieces(local, arcs, links, threads, &c);
  c.bytes_sent += static_cast<int64_t>(arcs.size() * sizeof(ArcEnds)) * (links.pieces() - 1);
  if (counts && rank == 0)
    *counts = c;
  return paths;
}

} // namespace hoct
