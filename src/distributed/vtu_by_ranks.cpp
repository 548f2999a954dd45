#include "distributed/vtu_by_ranks.hpp"

#include "distributed/fingerprint_chain.hpp"
#include "distributed/mpi_exchange.hpp"
#include "io/vtu_cell_range.hpp"
#include "io/vtu_reader.hpp"
#include "mesh/mesh_partition.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace hoct {
namespace {

// A point id a rank's cells use, sent to a rank whose cells use points around it.
struct UsedBy {
  int64_t id;
  int64_t rank;
};

// Per point of `used` (ascending ids of the points this rank's cells use), the lowest and the
// highest rank whose cells use it. The ranks gather which blocks of `block` consecutive ids each
// uses (a bit per block, at most 65,536 blocks: io/vtu_cell_range); a rank sends another only
// its ids in blocks both use. Contiguous cells use a few runs of ids in the files simulations
// write, so what crosses is about the points the ranks share, plus the blocks' slack.
std::vector<std::array<int32_t, 2>> point_spans(const std::vector<int64_t> &used, int64_t block,
                                                std::size_t blocks, int rank, int ranks,
                                                MPI_Comm comm) {
  const std::size_t words = (blocks + 63) / 64;
  std::vector<uint64_t> mine(words, 0), all(words * static_cast<std::size_t>(ranks));
  for (const int64_t q : used)
    mine[static_cast<std::size_t>(q / block) / 64] |= uint64_t{1}
                                                      << (static_cast<std::size_t>(q / block) % 64);
  MPI_Allgather(mine.data(), static_cast<int>(words), MPI_UINT64_T, all.data(),
                static_cast<int>(words), MPI_UINT64_T, comm);
  std::vector<std::vector<UsedBy>> out(static_cast<std::size_t>(ranks));
  for (int s = 0; s < ranks; ++s) {
    if (s == rank)
      continue;
    const uint64_t *theirs = all.data() + static_cast<std::size_t>(s) * words;
    for (const int64_t q : used) {
      const std::size_t b = static_cast<std::size_t>(q / block);
      if ((theirs[b / 64] >> (b % 64)) & 1)
        out[static_cast<std::size_t>(s)].push_back(UsedBy{q, rank});
    }
  }
  std::vector<std::array<int32_t, 2>> span(used.size(), std::array<int32_t, 2>{rank, rank});
  for (const UsedBy &u : exchange_records(comm, out)) {
    const auto it = std::lower_bound(used.begin(), used.end(), u.id);
    if (it == used.end() || *it != u.id)
      continue;
    auto &s = span[static_cast<std::size_t>(it - used.begin())];
    s[0] = std::min(s[0], static_cast<int32_t>(u.rank));
    s[1] = std::max(s[1], static_cast<int32_t>(u.rank));
  }
  return span;
}

// The whole's fingerprint, passed from rank to rank: each rank hashes the points it checked
// (consecutive in its arrays: their blocks were read) and its cells, in the file's order.
uint64_t fingerprint_of_parts(const VtuCellRange &v, int64_t whole_cells, int64_t whole_nodes,
                              bool with_kinds, MPI_Comm comm) {
  const MeshInput &m = v.input;
  const std::size_t n = static_cast<std::size_t>(v.check_end - v.check_begin),
                    at = n ? static_cast<std::size_t>(v.point_index(v.check_begin)) : 0;
  auto own = [&](int s, FingerprintState &fp) {
    if (s == kPointsSection) {
      fingerprint_words(fp, m.points.data() + at, 3 * n);
    } else if (s == kValuesSection) {
      fingerprint_words(fp, m.values.data() + at, n);
    } else if (s == kNodesSection) {
      fingerprint_words(fp, m.cell_nodes.data(), m.cell_nodes.size());
    } else {
      fingerprint_cell_bytes(fp, s == kDegreesSection ? m.cell_degree : m.cell_kind, m.num_cells());
    }
  };
  return fingerprint_by_ranks(comm, {v.file_points, v.file_points, whole_cells, whole_nodes},
                              with_kinds, own);
}

// This rank's share from the blocks it read: the points its cells use, in the whole's order
// (marked over the points it read, block after block), and their spans.
void by_blocks(VtuCellRange &v, MeshPiece &piece, int rank, int ranks, MPI_Comm comm) {
  MeshInput &m = v.input;
  UninitializedVector<int64_t> local(m.points.size());
  std::fill(local.begin(), local.end(), int64_t{-1});
  for (const int64_t q : m.cell_nodes)
    local[static_cast<std::size_t>(v.point_index(q))] = 0;
  std::vector<int64_t> used;
  used.reserve(m.points.size());
  for (std::size_t b = 0; b < v.block_first.size(); ++b) {
    if (v.block_first[b] < 0)
      continue;
    const int64_t id = static_cast<int64_t>(b) * v.point_block;
    const int64_t count = std::min(v.point_block, v.file_points - id);
    for (int64_t i = 0; i < count; ++i) {
      int64_t &k = local[static_cast<std::size_t>(v.block_first[b] + i)];
      if (k == 0) {
        k = static_cast<int64_t>(used.size());
        used.push_back(id + i);
      }
    }
  }
  piece.point_span = point_spans(used, v.point_block, v.block_first.size(), rank, ranks, comm);
  MeshInput &out = piece.input;
  if (used.size() == m.points.size()) { // every point it read: the arrays themselves
    out.points = std::move(m.points);
    out.values = std::move(m.values);
  } else {
    out.points.resize(used.size());
    out.values.resize(used.size());
    for (std::size_t i = 0; i < used.size(); ++i) {
      const std::size_t k = static_cast<std::size_t>(v.point_index(used[i]));
      out.points[i] = m.points[k];
      out.values[i] = m.values[k];
    }
    m.points = {};
    m.values = {};
  }
  for (int64_t &q : m.cell_nodes)
    q = local[static_cast<std::size_t>(v.point_index(q))];
  piece.global_point = std::move(used);
}

// A point id a rank's cells use, asked of the rank that checked it.
struct PointAsk {
  int64_t id;
  int64_t rank;
};
// The answer: the point, its value and its span over the ranks whose cells use it.
struct PointGot {
  int64_t id;
  Vec3 point;
  double value;
  std::array<int32_t, 2> span;
};

// The points of `used` (ascending ids) and their spans, from the ranks that read and checked
// them ([np r / R, np (r + 1) / R) on rank r): for a file whose points are numbered at random,
// where the blocks of ids the ranks use all overlap. Every rank asks for all it uses; what
// crosses is about the points each uses, once.
std::vector<PointGot> points_from_owners(const VtuCellRange &v, const std::vector<int64_t> &used,
                                         int rank, int ranks, MPI_Comm comm) {
  const int64_t np = v.file_points, nr = ranks;
  const auto owner = [&](int64_t q) {
    int64_t r = std::min(nr - 1, q * nr / np);
    while (r + 1 < nr && np * (r + 1) / nr <= q)
      ++r;
    while (r > 0 && np * r / nr > q)
      --r;
    return static_cast<std::size_t>(r);
  };
  std::vector<std::vector<PointAsk>> asks(static_cast<std::size_t>(ranks));
  for (const int64_t q : used)
    asks[owner(q)].push_back(PointAsk{q, rank});
  std::vector<PointAsk> asked = exchange_records(comm, asks);
  std::sort(asked.begin(), asked.end(), [](const PointAsk &a, const PointAsk &b) {
    return a.id < b.id || (a.id == b.id && a.rank < b.rank);
  });
  std::vector<std::vector<PointGot>> answers(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < asked.size();) {
    std::size_t j = i + 1;
    while (j < asked.size() && asked[j].id == asked[i].id)
      ++j;
    const int64_t q = asked[i].id;
    if (q < v.check_begin || q >= v.check_end)
      throw std::logic_error("points_from_owners: asked for a point another rank checked");
    const std::size_t k = static_cast<std::size_t>(v.point_index(q));
    const std::array<int32_t, 2> span{static_cast<int32_t>(asked[i].rank),
                                      static_cast<int32_t>(asked[j - 1].rank)};
    for (std::size_t a = i; a < j; ++a)
      answers[static_cast<std::size_t>(asked[a].rank)].push_back(
          PointGot{q, v.input.points[k], v.input.values[k], span});
    i = j;
  }
  // From the owners in rank order, each in ascending ids: ascending ids in all.
  std::vector<PointGot> got = exchange_records(comm, answers);
  bool same = got.size() == used.size();
  for (std::size_t i = 0; same && i < got.size(); ++i)
    same = got[i].id == used[i];
  if (!same)
    throw std::logic_error("points_from_owners: the answers are not the points asked for");
  return got;
}

} // namespace

RankRead read_vtu_by_ranks(const std::string &path, const FieldSelection &field,
                           const ReadLimits &limits, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  RankRead read;
  std::optional<VtuCellRange> got;
  std::string why;
  bool failed = false;
  try {
    got = read_vtu_cell_range(path, field, limits, rank, ranks, why);
  } catch (const std::exception &) { // rank 0 reads the whole, which reports it
    failed = true;
  }
  // The reason of the lowest rank that cannot read its part: a problem in the file first.
  int mine = failed ? 0 : got ? 2 : 1, fewest = mine;
  MPI_Allreduce(&mine, &fewest, 1, MPI_INT, MPI_MIN, comm);
  if (fewest == 0) {
    read.fallback = "a rank found a problem in its part";
    return read;
  }
  if (fewest == 1) {
    int first = got ? ranks : rank, lowest = first;
    MPI_Allreduce(&first, &lowest, 1, MPI_INT, MPI_MIN, comm);
    uint64_t size = why.size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, lowest, comm);
    why.resize(static_cast<std::size_t>(size));
    MPI_Bcast(why.data(), static_cast<int>(size), MPI_CHAR, lowest, comm);
    read.fallback = why;
    return read;
  }
  VtuCellRange &v = *got;
  MeshInput &m = v.input;

  // The whole's counts.
  int64_t triangles = static_cast<int64_t>(m.num_cells());
  for (std::size_t c = 0; c < m.num_cells() && !m.cell_kind.empty(); ++c)
    triangles += is_quadrilateral(m.kind(c)) ? 1 : 0;
  int64_t sums[3] = {static_cast<int64_t>(m.num_cells()), static_cast<int64_t>(m.cell_nodes.size()),
                     m.lagrange_triangles_only() ? 0 : 1};
  MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_INT64_T, MPI_SUM, comm);
  const int64_t whole_cells = sums[0];
  if (whole_cells == 0) {
    read.fallback = "the file has no surface cells";
    return read;
  }
  const uint64_t fingerprint = fingerprint_of_parts(v, whole_cells, sums[1], sums[2] > 0, comm);

  // This rank's share: the points its cells use, in the whole's order, and their spans. Points
  // numbered at random (a part read its checked share alone): every rank gets the points its
  // cells use from the ranks that checked them.
  int from_owners = v.used_points_read ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &from_owners, 1, MPI_INT, MPI_MAX, comm);
  RankInput in;
  MeshPiece &piece = in.piece;
  MeshInput &out = piece.input;
  if (from_owners) {
    read.note = "its points are numbered far from their cells: each rank read its share of the "
                "points and got its cells' points from the ranks that read them";
    // The ids its cells use, ascending, each cell node renumbered to its index among them: one
    // sort of (id, node) pairs.
    std::vector<std::array<int64_t, 2>> nodes(m.cell_nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k)
      nodes[k] = {m.cell_nodes[k], static_cast<int64_t>(k)};
    std::sort(nodes.begin(), nodes.end());
    std::vector<int64_t> used;
    for (const auto &[q, k] : nodes) {
      if (used.empty() || used.back() != q)
        used.push_back(q);
      m.cell_nodes[static_cast<std::size_t>(k)] = static_cast<int64_t>(used.size()) - 1;
    }
    std::vector<std::array<int64_t, 2>>().swap(nodes);
    const std::vector<PointGot> got = points_from_owners(v, used, rank, ranks, comm);
    m.points = {};
    m.values = {};
    out.points.resize(used.size());
    out.values.resize(used.size());
    piece.point_span.resize(used.size());
    for (std::size_t i = 0; i < used.size(); ++i) {
      out.points[i] = got[i].point;
      out.values[i] = got[i].value;
      piece.point_span[i] = got[i].span;
    }
    piece.global_point = std::move(used);
  } else {
    by_blocks(v, piece, rank, ranks, comm);
  }
  out.source = m.source;
  out.field_name = m.field_name;
  out.coordinate_precision = m.coordinate_precision;
  out.value_precision = m.value_precision;
  out.cell_offsets = std::move(m.cell_offsets);
  out.cell_degree = std::move(m.cell_degree);
  out.cell_kind = std::move(m.cell_kind);
  out.cell_nodes = std::move(m.cell_nodes);
  piece.first_cell = exclusive_sum(comm, static_cast<int64_t>(out.num_cells()));
  in.first_triangle = exclusive_sum(comm, triangles);
  in.whole_cells = whole_cells;
  in.whole_points = v.file_points;
  in.cells_split = sums[2] > 0;
  in.source = out.source;
  in.field_name = out.field_name;
  if (rank == 0)
    in.fingerprint = InputFingerprint{v.file_points, whole_cells, out.field_name, fingerprint};
  in.read_whole = [path, field, limits, rank] {
    return rank == 0 ? read_vtu(path, field, limits) : MeshInput{};
  };
  read.input = std::move(in);
  return read;
}

} // namespace hoct
