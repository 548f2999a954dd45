#include "distributed/distributed_checks.hpp"

#include "mesh/duplicate_points.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

namespace hoct {

SurfaceShape gather_surface(MPI_Comm comm, const PieceSurface *own) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const std::vector<std::byte> bytes = own ? encode_piece_surface(*own) : std::vector<std::byte>{};
  if (bytes.size() > static_cast<std::size_t>(INT_MAX))
    throw Error("a piece's seams take more than 2 GiB: use more ranks");
  int n = static_cast<int>(bytes.size());
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
      throw Error("the pieces' seams take more than 2 GiB on rank 0");
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(bytes.data(), n, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0,
              comm);
  if (rank != 0)
    return {};
  std::vector<PieceSurface> pieces;
  for (int r = 0; r < ranks; ++r)
    if (sizes[r] > 0)
      pieces.push_back(decode_piece_surface(
          std::span<const std::byte>(all.data() + offsets[r], static_cast<std::size_t>(sizes[r]))));
  return glue_pieces(pieces);
}

namespace {

struct Located {
  Vec3 p;
  int64_t id;
};

uint64_t mix(uint64_t x) {
  x ^= x >> 31;
  x *= 0x9e3779b97f4a7c15ull;
  x ^= x >> 29;
  x *= 0xd6e8feb86659fd93ull;
  return x ^ (x >> 32);
}

} // namespace

bool duplicate_vertices_across(MPI_Comm comm, std::span<const Vec3> positions,
                               std::span<const int64_t> ids, double tolerance, const Vec3 &origin,
                               int threads) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  // Grid cells of 64 tolerances: a vertex goes to the owner of every cell its tolerance box
  // meets (one, near a face two to eight), so any two within the tolerance meet at the owner of
  // either one's own cell.
  const double h = tolerance > 0 ? 64 * tolerance : 1.0;
  auto owner = [&](int64_t i, int64_t j, int64_t k) {
    const uint64_t x = mix(static_cast<uint64_t>(i) ^
                           mix(static_cast<uint64_t>(j) ^ mix(static_cast<uint64_t>(k))));
    return static_cast<int>(x % static_cast<uint64_t>(ranks));
  };
  std::vector<std::vector<Located>> out(static_cast<std::size_t>(ranks));
  int to[8];
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const Vec3 &p = positions[v];
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = static_cast<int64_t>(std::floor((p[a] - origin[a] - tolerance) / h));
      hi[a] = static_cast<int64_t>(std::floor((p[a] - origin[a] + tolerance) / h));
    }
    int n = 0;
    for (int64_t i = lo[0]; i <= hi[0]; ++i)
      for (int64_t j = lo[1]; j <= hi[1]; ++j)
        for (int64_t k = lo[2]; k <= hi[2]; ++k) {
          const int r = owner(i, j, k);
          if (std::find(to, to + n, r) == to + n)
            to[n++] = r;
        }
    for (int m = 0; m < n; ++m)
      out[static_cast<std::size_t>(to[m])].push_back(Located{p, ids[v]});
  }
  std::vector<int> send_counts(static_cast<std::size_t>(ranks)),
      send_offsets(static_cast<std::size_t>(ranks)),
      receive_counts(static_cast<std::size_t>(ranks)),
      receive_offsets(static_cast<std::size_t>(ranks));
  std::vector<Located> sending;
  for (int r = 0; r < ranks; ++r) {
    if (out[r].size() > static_cast<std::size_t>(INT_MAX) / sizeof(Located))
      throw Error("a rank sends more than 2 GiB of vertices to another: use more ranks");
    send_offsets[r] = static_cast<int>(sending.size() * sizeof(Located));
    send_counts[r] = static_cast<int>(out[r].size() * sizeof(Located));
    sending.insert(sending.end(), out[r].begin(), out[r].end());
    std::vector<Located>().swap(out[r]);
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm);
  int64_t total = 0;
  for (int r = 0; r < ranks; ++r) {
    receive_offsets[r] = static_cast<int>(total);
    total += receive_counts[r];
  }
  if (total > INT_MAX)
    throw Error("a rank receives more than 2 GiB of vertices: use more ranks");
  std::vector<Located> received(static_cast<std::size_t>(total) / sizeof(Located));
  MPI_Alltoallv(sending.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, received.data(),
                receive_counts.data(), receive_offsets.data(), MPI_BYTE, comm);
  std::vector<Located>().swap(sending);
  std::vector<Vec3> points(received.size());
  std::vector<int64_t> all(received.size());
  for (std::size_t i = 0; i < received.size(); ++i) {
    points[i] = received[i].p;
    all[i] = static_cast<int64_t>(i);
  }
  const std::vector<int64_t> group = coincident_points(points, all, tolerance, threads);
  int found = 0;
  for (std::size_t i = 0; i < received.size() && !found; ++i)
    found = received[static_cast<std::size_t>(group[i])].id != received[i].id;
  MPI_Allreduce(MPI_IN_PLACE, &found, 1, MPI_INT, MPI_MAX, comm);
  return found != 0;
}

} // namespace hoct
