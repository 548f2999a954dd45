#include "distributed/distributed_checks.hpp"

#include "distributed/mpi_exchange.hpp"
#include "mesh/duplicate_points.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

namespace hoct {

SurfaceShape merge_surfaces(MPI_Comm comm, PieceSurface own) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  constexpr int kTag = 79;
  for (int step = 1; step < ranks; step *= 2) {
    if (rank % (2 * step) != 0) { // the group's summary to the rank it merges into
      const std::vector<std::byte> bytes = encode_piece_surface(own);
      if (bytes.size() > static_cast<std::size_t>(INT_MAX))
        throw Error("a group of pieces' seam band takes 2 GiB or more: use more ranks");
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, rank - step, kTag, comm);
      return SurfaceShape{};
    }
    if (rank + step < ranks) {
      MPI_Status status;
      MPI_Probe(rank + step, kTag, comm, &status);
      int n = 0;
      MPI_Get_count(&status, MPI_BYTE, &n);
      std::vector<std::byte> bytes(static_cast<std::size_t>(n));
      MPI_Recv(bytes.data(), n, MPI_BYTE, rank + step, kTag, comm, MPI_STATUS_IGNORE);
      own = merge_piece_surfaces(own, decode_piece_surface(bytes));
    }
  }
  return surface_shape(own);
}

namespace {

struct Located {
  Vec3 p;
  int64_t id;
};

} // namespace

ToleranceGrid::ToleranceGrid(const std::array<Vec3, 2> &box, double tolerance)
    : origin_(box[0]), reach_(3 * tolerance) {
  const double extent =
      std::max({box[1][0] - box[0][0], box[1][1] - box[0][1], box[1][2] - box[0][2]});
  const double coarse = std::max(extent / 256, 8 * tolerance);
  inv_coarse_ = coarse > 0 ? 1 / coarse : 1.0;
  inv_fine_ = tolerance > 0 ? 1 / (64 * tolerance) : 1.0;
}

std::vector<uint8_t> ToleranceGrid::near_other_labels(MPI_Comm comm,
                                                      std::span<const Vec3> positions, int64_t base,
                                                      std::span<const uint32_t> label) const {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  // Each run of a label: its coarse cells (a bit each, cleared after the run) claimed at their
  // owners, which answer the cells claimed under two labels or more.
  struct Claim {
    uint64_t key;
    int64_t label;
    int64_t rank;
  };
  auto label_of = [&](std::size_t i) {
    return base + (label.empty() ? 0 : static_cast<int64_t>(label[i]));
  };
  std::vector<uint64_t> bits(kCoarseCells / 64 + 1, 0);
  std::vector<uint64_t> keys;
  std::vector<std::vector<Claim>> claims(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < positions.size();) {
    std::size_t j = i;
    keys.clear();
    for (; j < positions.size() && label_of(j) == label_of(i); ++j)
      for_coarse(positions[j], [&](uint64_t key) {
        if (!(bits[key >> 6] >> (key & 63) & 1)) {
          bits[key >> 6] |= uint64_t{1} << (key & 63);
          keys.push_back(key);
        }
      });
    for (const uint64_t key : keys) {
      bits[key >> 6] = 0;
      claims[static_cast<std::size_t>(owner(key, ranks))].push_back({key, label_of(i), rank});
    }
    i = j;
  }
  std::vector<Claim> claimed = exchange_records(comm, claims);
  std::sort(claimed.begin(), claimed.end(), [](const Claim &a, const Claim &b) {
    return a.key != b.key ? a.key < b.key : a.label < b.label;
  });
  std::vector<std::vector<uint64_t>> answers(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < claimed.size();) {
    std::size_t j = i;
    while (j < claimed.size() && claimed[j].key == claimed[i].key)
      ++j;
    if (claimed[j - 1].label != claimed[i].label)
      for (std::size_t k = i; k < j; ++k)
        answers[static_cast<std::size_t>(claimed[k].rank)].push_back(claimed[k].key);
    i = j;
  }
  for (const uint64_t key : exchange_records(comm, answers))
    bits[key >> 6] |= uint64_t{1} << (key & 63);
  std::vector<uint8_t> near(positions.size(), 0);
  for (std::size_t v = 0; v < positions.size(); ++v)
    for_coarse(positions[v], [&](uint64_t key) { near[v] |= bits[key >> 6] >> (key & 63) & 1; });
  return near;
}

int ToleranceGrid::fine_owners(const Vec3 &p, int ranks, int to[8]) const {
  int n = 0;
  for_cells(p, inv_fine_, reach_, [&](int64_t i, int64_t j, int64_t k) {
    const int r = fine_owner(i, j, k, ranks);
    if (std::find(to, to + n, r) == to + n)
      to[n++] = r;
  });
  return n;
}

bool duplicate_vertices_across(MPI_Comm comm, std::span<const Vec3> positions,
                               std::span<const int64_t> ids, double tolerance,
                               const std::array<Vec3, 2> &box, int threads) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1)
    return false;
  // The vertices where another rank's may be near, to the owners of the fine cells their box
  // meets: any two within the tolerance meet at the owner of either one's own cell.
  const ToleranceGrid grid(box, tolerance);
  const std::vector<uint8_t> near = grid.near_other_labels(comm, positions, rank, {});
  std::vector<std::vector<Located>> out(static_cast<std::size_t>(ranks));
  int to[8];
  for (std::size_t v = 0; v < positions.size(); ++v) {
    if (!near[v])
      continue;
    const int n = grid.fine_owners(positions[v], ranks, to);
    for (int m = 0; m < n; ++m)
      out[static_cast<std::size_t>(to[m])].push_back(Located{positions[v], ids[v]});
  }
  const std::vector<Located> received = exchange_records(comm, out);
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
