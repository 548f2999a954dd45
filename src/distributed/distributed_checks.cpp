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

// floor(x) for |x| < 2^62 (std::floor is a library call without SSE4.1).
int64_t floor_int(double x) {
  const int64_t i = static_cast<int64_t>(x);
  return i - (x < static_cast<double>(i));
}

// MPI_Alltoallv of trivially copyable records, out[r] to rank r; what every rank sent here, in
// rank order.
template <class T>
std::vector<T> exchange(MPI_Comm comm, std::vector<std::vector<T>> &out, int ranks) {
  std::vector<int> send_counts(static_cast<std::size_t>(ranks)),
      send_offsets(static_cast<std::size_t>(ranks)),
      receive_counts(static_cast<std::size_t>(ranks)),
      receive_offsets(static_cast<std::size_t>(ranks));
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

} // namespace

bool duplicate_vertices_across(MPI_Comm comm, std::span<const Vec3> positions,
                               std::span<const int64_t> ids, double tolerance,
                               const std::array<Vec3, 2> &box, int threads) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1)
    return false;
  const Vec3 &origin = box[0];
  // Grid cells (1 / `inverse` wide) whose keys (i, j, k) a vertex's box of twice the tolerance
  // meets (one, near a face two to eight): any two vertices within the tolerance both meet the
  // cell of either one, whatever the rounding.
  const double reach = 2 * tolerance;
  auto for_cells = [&](const Vec3 &p, double inverse, auto &&f) {
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = floor_int((p[a] - origin[a] - reach) * inverse);
      hi[a] = floor_int((p[a] - origin[a] + reach) * inverse);
    }
    for (int64_t i = lo[0]; i <= hi[0]; ++i)
      for (int64_t j = lo[1]; j <= hi[1]; ++j)
        for (int64_t k = lo[2]; k <= hi[2]; ++k)
          f(i, j, k);
  };
  auto owner = [&](uint64_t key) {
    return static_cast<int>(mix(key) % static_cast<uint64_t>(ranks));
  };

  // 1. The coarse cells (about 256 along the box's longest side) that hold vertices of several
  // ranks: each rank's cells to their owners, which count the ranks and answer.
  const double extent =
      std::max({box[1][0] - box[0][0], box[1][1] - box[0][1], box[1][2] - box[0][2]});
  const double coarse =
      std::max(extent / 256, 8 * tolerance) > 0 ? std::max(extent / 256, 8 * tolerance) : 1.0;
  const double inv_coarse = 1 / coarse;
  // At most 258 cells a side (the boxes reach one beyond the box's cells): a bit per cell.
  constexpr uint64_t kSide = 260;
  auto coarse_key = [](int64_t i, int64_t j, int64_t k) {
    return (static_cast<uint64_t>(i + 1) * kSide + static_cast<uint64_t>(j + 1)) * kSide +
           static_cast<uint64_t>(k + 1);
  };
  std::vector<uint64_t> bits(kSide * kSide * kSide / 64 + 1, 0);
  for (const Vec3 &p : positions)
    for_cells(p, inv_coarse, [&](int64_t i, int64_t j, int64_t k) {
      const uint64_t key = coarse_key(i, j, k);
      bits[key >> 6] |= uint64_t{1} << (key & 63);
    });
  std::vector<uint64_t> mine;
  for (std::size_t w = 0; w < bits.size(); ++w)
    for (uint64_t b = bits[w]; b != 0; b &= b - 1)
      mine.push_back(64 * w + static_cast<uint64_t>(__builtin_ctzll(b)));
  struct Claim {
    uint64_t key;
    int64_t rank;
  };
  std::vector<std::vector<Claim>> claims(static_cast<std::size_t>(ranks));
  for (const uint64_t key : mine)
    claims[static_cast<std::size_t>(owner(key))].push_back({key, rank});
  std::vector<Claim> claimed = exchange(comm, claims, ranks);
  std::sort(claimed.begin(), claimed.end(),
            [](const Claim &a, const Claim &b) { return a.key < b.key; });
  std::vector<std::vector<uint64_t>> answers(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < claimed.size();) {
    std::size_t j = i;
    while (j < claimed.size() && claimed[j].key == claimed[i].key)
      ++j;
    if (j - i > 1) // each rank claims a cell once
      for (std::size_t k = i; k < j; ++k)
        answers[static_cast<std::size_t>(claimed[k].rank)].push_back(claimed[k].key);
    i = j;
  }
  const std::vector<uint64_t> shared = exchange(comm, answers, ranks);
  std::fill(bits.begin(), bits.end(), uint64_t{0}); // now: the shared cells
  for (const uint64_t key : shared)
    bits[key >> 6] |= uint64_t{1} << (key & 63);

  // 2. The vertices there, to the owners of the fine cells (64 tolerances) their tolerance box
  // meets: any two within the tolerance meet at the owner of either one's own cell.
  const double fine = tolerance > 0 ? 64 * tolerance : 1.0;
  const double inv_fine = 1 / fine;
  std::vector<std::vector<Located>> out(static_cast<std::size_t>(ranks));
  int to[8];
  for (std::size_t v = 0; v < positions.size() && !shared.empty(); ++v) {
    const Vec3 &p = positions[v];
    bool there = false;
    for_cells(p, inv_coarse, [&](int64_t i, int64_t j, int64_t k) {
      const uint64_t key = coarse_key(i, j, k);
      there = there || (bits[key >> 6] >> (key & 63) & 1);
    });
    if (!there)
      continue;
    int n = 0;
    for_cells(p, inv_fine, [&](int64_t i, int64_t j, int64_t k) {
      const int r = owner(mix(static_cast<uint64_t>(i)) ^ mix(static_cast<uint64_t>(j) + 1) ^
                          mix(static_cast<uint64_t>(k) + 2));
      if (std::find(to, to + n, r) == to + n)
        to[n++] = r;
    });
    for (int m = 0; m < n; ++m)
      out[static_cast<std::size_t>(to[m])].push_back(Located{p, ids[v]});
  }
  const std::vector<Located> received = exchange(comm, out, ranks);
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
