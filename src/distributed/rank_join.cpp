#include "distributed/rank_join.hpp"

#include "distributed/distributed_checks.hpp"
#include "distributed/fingerprint_chain.hpp"
#include "distributed/mpi_exchange.hpp"
#include "io/piece_join.hpp"
#include "mesh/duplicate_points.hpp"
#include "mesh/mesh_fingerprint.hpp"
#include "mesh/mesh_partition.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <type_traits>

namespace hoct {
namespace {

// As join_pieces: positions within this of the bounding-box diagonal, values of the largest
// magnitude, are the same.
constexpr double kRelativeTolerance = 1e-9;

bool all_ranks(MPI_Comm comm, bool ok) {
  int v = ok ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_MIN, comm);
  return v != 0;
}

// A copy of a point (a piece's) sent to the rank that decides which point of the whole it is.
struct Copy {
  Vec3 p;
  double value;
  int64_t id;    // its global id (merging by ids)
  int64_t local; // its index on its rank
  int32_t rank, piece;
  int32_t used; // a kept cell uses it
  int32_t pad;
};

// The decision, back to a copy's rank: the copy that is its point in the whole (its
// representative: itself, or a copy it is merged with) and the point's span over the ranks.
struct Decision {
  Vec3 rep_p;
  double rep_value;
  int64_t local, rep_local;
  int32_t rep_rank, span_lo, span_hi, pad;
};

struct Ask {
  int64_t rep_local, local;
  int64_t rank;
};

struct Answer {
  int64_t local, global;
};

// Per point of this rank's pieces (`n` of them, merging by ids): whether another copy of its id
// may exist, at block granularity: the ids are cut into at most 65,536 blocks of consecutive ids;
// a block two ranks hold, or with an id this rank holds twice, is shared. A copy in no shared block
// has no other copy: its owner would decide it stays, so it need not be sent. Collective. Empty
// (every copy sent) for negative ids.
std::vector<uint8_t> shared_id_blocks(MPI_Comm comm, const PieceParts &parts, std::size_t n) {
  int64_t range[2] = {std::numeric_limits<int64_t>::max(), -1}; // -min, max
  for (std::size_t i = 0; i < n; ++i) {
    range[0] = std::min(range[0], parts.global[i]);
    range[1] = std::max(range[1], parts.global[i]);
  }
  range[0] = -range[0];
  MPI_Allreduce(MPI_IN_PLACE, range, 2, MPI_INT64_T, MPI_MAX, comm);
  if (-range[0] < 0 || range[1] < 0)
    return {};
  const int64_t block = std::max<int64_t>(1024, range[1] / 65536 + 1);
  const std::size_t blocks = static_cast<std::size_t>(range[1] / block + 1);
  // Per block: 1 held by this rank, 2 if it holds an id of it twice (two of its pieces' copies,
  // or two in one piece); summed over the ranks, a block counts 2 or more where it is shared.
  // The ids seen: a bit per id of each block the rank holds.
  const std::size_t words = static_cast<std::size_t>((block + 63) / 64);
  std::vector<int32_t> held(blocks, 0);
  std::vector<int64_t> slot(blocks, -1);
  std::vector<uint64_t> seen;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t b = static_cast<std::size_t>(parts.global[i] / block);
    if (slot[b] < 0) {
      slot[b] = static_cast<int64_t>(seen.size());
      seen.resize(seen.size() + words, 0);
      held[b] = 1;
    }
    const std::size_t bit = static_cast<std::size_t>(parts.global[i] % block);
    uint64_t &word = seen[static_cast<std::size_t>(slot[b]) + bit / 64];
    if (word >> (bit % 64) & 1)
      held[b] = 2;
    word |= uint64_t{1} << (bit % 64);
  }
  MPI_Allreduce(MPI_IN_PLACE, held.data(), static_cast<int>(blocks), MPI_INT32_T, MPI_SUM, comm);
  std::vector<uint8_t> shared(n);
  for (std::size_t i = 0; i < n; ++i)
    shared[i] = held[static_cast<std::size_t>(parts.global[i] / block)] >= 2;
  return shared;
}

bool before(const Copy &a, const Copy &b) {
  return a.rank != b.rank ? a.rank < b.rank : a.local < b.local;
}

// A group of copies, ascending in the whole's order, that are one point in the whole for
// join_pieces: by ids every copy is the first's; by position the copies of other pieces than
// the first's are the first's, the first's piece's own copies stay points of their own.
void decide(std::span<const Copy> group, bool by_ids, std::vector<std::vector<Decision>> &out) {
  const Copy &rep = group.front();
  std::vector<int32_t> lo(group.size(), -1), hi(group.size(), -1);
  auto target = [&](const Copy &c) -> std::size_t {
    return by_ids || c.piece != rep.piece ? 0 : static_cast<std::size_t>(&c - group.data());
  };
  for (const Copy &c : group) {
    if (!c.used)
      continue;
    const std::size_t t = target(c);
    lo[t] = lo[t] < 0 ? c.rank : std::min(lo[t], c.rank);
    hi[t] = std::max(hi[t], c.rank);
  }
  for (const Copy &c : group) {
    const std::size_t t = target(c);
    const Copy &to = group[t];
    out[static_cast<std::size_t>(c.rank)].push_back(
        Decision{to.p, to.value, c.local, to.local, to.rank, lo[t], hi[t], 0});
  }
}

} // namespace

RankRead join_rank_pieces(std::vector<FilePiece> pieces, const std::string &failure,
                          const std::string &source, const ReadLimits &limits, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  RankRead result;
  auto fall_back = [&](const std::string &why) {
    result.fallback = why;
    return result;
  };

  // 1. This rank's pieces, each one's ghosts dropped, one after the other; their numbers among
  // all ranks' pieces.
  const int64_t first = exclusive_sum(comm, static_cast<int64_t>(pieces.size()));
  PieceParts parts;
  std::string problem = failure;
  if (problem.empty()) {
    try {
      parts = concatenate_pieces(pieces, source, /*by_ids=*/true);
    } catch (const std::exception &e) {
      problem = e.what();
    }
  }
  if (!all_ranks(comm, problem.empty()))
    return fall_back("a piece could not be read or joined alone");
  MeshInput &m = parts.mesh;
  const std::size_t n = m.points.size();

  // 2. What the join decides from all pieces: merging by ids, the tolerances, the field.
  int64_t sums[3] = {static_cast<int64_t>(parts.filled), static_cast<int64_t>(m.num_cells()),
                     m.lagrange_triangles_only() ? 0 : 1};
  MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_INT64_T, MPI_SUM, comm);
  const bool ids = all_ranks(comm, parts.ids);
  const std::array<Vec3, 2> own_box = bounding_box(m.points, limits.threads);
  double scale = 0;
  for (const double v : m.values)
    scale = std::max(scale, std::abs(v));
  // The whole's bounding box, largest precisions and largest value magnitude: one reduction.
  const double inf = std::numeric_limits<double>::infinity();
  double most[9] = {n ? -own_box[0][0] : -inf, n ? -own_box[0][1] : -inf, n ? -own_box[0][2] : -inf,
                    n ? own_box[1][0] : -inf,  n ? own_box[1][1] : -inf,  n ? own_box[1][2] : -inf,
                    m.coordinate_precision,    m.value_precision,         scale};
  MPI_Allreduce(MPI_IN_PLACE, most, 9, MPI_DOUBLE, MPI_MAX, comm);
  const double value_precision = most[7];
  scale = most[8];
  // The field's name, from the first rank with a piece that is not empty: the same on all.
  int named = parts.filled > 0 ? rank : ranks;
  MPI_Allreduce(MPI_IN_PLACE, &named, 1, MPI_INT, MPI_MIN, comm);
  std::string field_name = named == rank ? m.field_name : std::string();
  if (named < ranks) {
    uint64_t size = field_name.size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, named, comm);
    field_name.resize(size);
    MPI_Bcast(field_name.data(), static_cast<int>(size), MPI_CHAR, named, comm);
  }
  if (!all_ranks(comm, parts.filled == 0 || m.field_name == field_name))
    return fall_back("the pieces' fields differ");
  if (sums[0] == 0 || sums[1] == 0)
    return fall_back("no piece with cells");
  const std::array<Vec3, 2> box = {Vec3{-most[0], -most[1], -most[2]},
                                   Vec3{most[3], most[4], most[5]}};
  const double diagonal =
      std::hypot(box[1][0] - box[0][0], box[1][1] - box[0][1], box[1][2] - box[0][2]);
  const double coordinate_precision = most[6];
  const double position_tolerance =
      ids ? diagonal * std::max(kRelativeTolerance, 4 * coordinate_precision)
          : kRelativeTolerance * diagonal;
  const double value_tolerance = kRelativeTolerance * scale;

  // 3. The copies that may be merged, to the ranks that decide: by id, every copy to its id's
  // owner; by position, the copies near another piece's to the owners of their fine cells.
  std::vector<uint8_t> used(n, 0);
  for (const int64_t q : m.cell_nodes)
    used[static_cast<std::size_t>(q)] = 1;
  auto copy_of = [&](std::size_t i) {
    return Copy{m.points[i],
                m.values[i],
                ids ? parts.global[i] : 0,
                static_cast<int64_t>(i),
                rank,
                static_cast<int32_t>(first + parts.piece_of[i]),
                used[i],
                0};
  };
  std::vector<std::vector<Copy>> sent(static_cast<std::size_t>(ranks));
  const ToleranceGrid grid(box, position_tolerance);
  if (sums[0] > 1) {
    if (ids) {
      const std::vector<uint8_t> shared = shared_id_blocks(comm, parts, n);
      for (std::size_t i = 0; i < n; ++i) {
        if (!shared.empty() && !shared[i])
          continue; // no other copy of its id anywhere: it stays, as its owner would decide
        const uint64_t h = static_cast<uint64_t>(parts.global[i]) * 0x9e3779b97f4a7c15ull;
        sent[(h >> 32) % static_cast<uint64_t>(ranks)].push_back(copy_of(i));
      }
    } else {
      const std::vector<uint8_t> near =
          grid.near_other_labels(comm, m.points, static_cast<int64_t>(first), parts.piece_of);
      int to[8];
      for (std::size_t i = 0; i < n; ++i) {
        if (!near[i])
          continue;
        const int k = grid.fine_owners(m.points[i], ranks, to);
        for (int j = 0; j < k; ++j)
          sent[static_cast<std::size_t>(to[j])].push_back(copy_of(i));
      }
    }
  }
  std::vector<Copy> received = exchange_records(comm, sent);

  // 4. The decisions. Where the ranks cannot be sure to decide as join_pieces would (copies of a
  // point that disagree, copies within the tolerance at positions that differ), they fall back.
  std::vector<std::vector<Decision>> decisions(static_cast<std::size_t>(ranks));
  bool sure = true;
  if (ids) {
    std::sort(received.begin(), received.end(), [](const Copy &a, const Copy &b) {
      return a.id != b.id ? a.id < b.id : before(a, b);
    });
    for (std::size_t i = 0; i < received.size();) {
      std::size_t j = i;
      while (j < received.size() && received[j].id == received[i].id)
        ++j;
      const Copy &rep = received[i];
      for (std::size_t k = i + 1; k < j && sure; ++k) {
        const Copy &c = received[k];
        sure = std::hypot(c.p[0] - rep.p[0], c.p[1] - rep.p[1], c.p[2] - rep.p[2]) <=
                   position_tolerance &&
               std::abs(c.value - rep.value) <= value_tolerance;
      }
      if (j - i > 1)
        decide(std::span<const Copy>(received.data() + i, j - i), true, decisions);
      i = j;
    }
  } else if (!received.empty()) {
    std::vector<Vec3> points(received.size());
    std::vector<int64_t> all(received.size());
    for (std::size_t i = 0; i < received.size(); ++i) {
      points[i] = received[i].p;
      all[i] = static_cast<int64_t>(i);
    }
    const std::vector<int64_t> group =
        coincident_points(points, all, position_tolerance, limits.threads);
    std::vector<std::size_t> order(received.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return group[a] != group[b] ? group[a] < group[b] : before(received[a], received[b]);
    });
    // A group is decided by the owner of its first copy's fine cell, which has every point
    // within two tolerances of that copy: if every copy of the group lies within the tolerance
    // of the first, any point within the tolerance of one of them is there too, so the group is
    // the whole join's. A group spread wider falls back.
    const double tol2 = position_tolerance * position_tolerance;
    std::vector<Copy> members;
    for (std::size_t i = 0; i < order.size();) {
      std::size_t j = i;
      while (j < order.size() && group[order[j]] == group[order[i]])
        ++j;
      members.clear();
      bool one_piece = true;
      for (std::size_t k = i; k < j; ++k) {
        // A copy that reached this rank twice (two of its fine cells are this rank's) counts once.
        const Copy &c = received[order[k]];
        if (!members.empty() && members.back().rank == c.rank && members.back().local == c.local)
          continue;
        members.push_back(c);
        one_piece = one_piece && c.piece == members.front().piece;
      }
      const Copy &f = members.front();
      if (!one_piece && grid.home_owner(f.p, ranks) == rank) {
        for (const Copy &c : members) {
          const double d2 = (c.p[0] - f.p[0]) * (c.p[0] - f.p[0]) +
                            (c.p[1] - f.p[1]) * (c.p[1] - f.p[1]) +
                            (c.p[2] - f.p[2]) * (c.p[2] - f.p[2]);
          sure = sure && d2 <= tol2 && std::abs(c.value - f.value) <= value_tolerance;
        }
        decide(members, false, decisions);
      }
      i = j;
    }
  }
  if (!all_ranks(comm, sure))
    return fall_back(ids ? "copies of a point disagree"
                         : "points of several pieces close together but not all within the "
                           "tolerance of one (or with values that differ)");
  std::vector<Decision> mine = exchange_records(comm, decisions);

  // 5. Every point's target (itself unless merged) and span; the whole's numbering of the
  // points that stay, then of the merged ones (asked of their representatives' ranks).
  // Most points have no decision (no copy elsewhere): theirs is to stay, their span this rank.
  // (Pooled arrays: the pages the reading freed serve here.)
  UninitializedVector<int32_t> decided(n);
  std::fill(decided.begin(), decided.end(), -1);
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const Decision &d = mine[k];
    const auto i = static_cast<std::size_t>(d.local);
    decided[i] = static_cast<int32_t>(k);
    m.points[i] = d.rep_p;
    m.values[i] = d.rep_value;
  }
  auto stays = [&](std::size_t i) {
    const int32_t k = decided[i];
    return k < 0 || (mine[k].rep_rank == rank && mine[k].rep_local == static_cast<int64_t>(i));
  };
  auto span_of = [&](std::size_t i) {
    const int32_t k = decided[i];
    if (k >= 0)
      return std::array<int32_t, 2>{mine[k].span_lo, mine[k].span_hi};
    return used[i] ? std::array<int32_t, 2>{rank, rank} : std::array<int32_t, 2>{-1, -1};
  };
  int64_t stay = 0;
  for (std::size_t i = 0; i < n; ++i)
    stay += stays(i);
  const int64_t base = exclusive_sum(comm, stay);
  UninitializedVector<int64_t> global(n);
  int64_t next = base;
  std::vector<std::vector<Ask>> asks(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < n; ++i) {
    if (stays(i)) {
      global[i] = next++;
    } else {
      const Decision &d = mine[static_cast<std::size_t>(decided[i])];
      asks[static_cast<std::size_t>(d.rep_rank)].push_back(
          Ask{d.rep_local, static_cast<int64_t>(i), rank});
    }
  }
  std::vector<std::vector<Answer>> answers(static_cast<std::size_t>(ranks));
  for (const Ask &a : exchange_records(comm, asks))
    answers[static_cast<std::size_t>(a.rank)].push_back(
        Answer{a.local, global[static_cast<std::size_t>(a.rep_local)]});
  for (const Answer &a : exchange_records(comm, answers))
    global[static_cast<std::size_t>(a.local)] = a.global;

  // 6. The whole's fingerprint, passed from rank to rank section by section: the points and
  // values that stay, the cells' degrees, their nodes (the whole's ids) and kinds.
  int64_t totals[2] = {stay, static_cast<int64_t>(m.cell_nodes.size())};
  MPI_Allreduce(MPI_IN_PLACE, totals, 2, MPI_INT64_T, MPI_SUM, comm);
  const int64_t whole_points = totals[0], whole_cells = sums[1];
  const bool with_kinds = sums[2] > 0;
  auto own = [&](int s, FingerprintState &fp) {
    if (s == kPointsSection || s == kValuesSection) {
      // Runs of points that stay, hashed in place.
      for (std::size_t i = 0; i < n;) {
        std::size_t j = i;
        while (j < n && stays(j))
          ++j;
        if (s == kPointsSection)
          fingerprint_words(fp, m.points.data() + i, 3 * (j - i));
        else
          fingerprint_words(fp, m.values.data() + i, j - i);
        i = j < n ? j + 1 : j;
      }
    } else if (s == kNodesSection) {
      int64_t nodes[4096];
      for (std::size_t k = 0; k < m.cell_nodes.size(); k += 4096) {
        const std::size_t end = std::min(m.cell_nodes.size(), k + 4096);
        for (std::size_t j = k; j < end; ++j)
          nodes[j - k] = global[static_cast<std::size_t>(m.cell_nodes[j])];
        fingerprint_words(fp, nodes, end - k);
      }
    } else {
      fingerprint_cell_bytes(fp, s == kDegreesSection ? m.cell_degree : m.cell_kind, m.num_cells());
    }
  };
  const uint64_t fingerprint = fingerprint_by_ranks(
      comm, {whole_points, whole_points, whole_cells, totals[1]}, with_kinds, own);

  // 7. This rank's share: its cells, the points they use in the whole's order, their spans.
  RankInput in;
  MeshPiece &piece = in.piece;
  // The points its cells use, in the whole's order: first the other ranks' (merged copies whose
  // representative is elsewhere, with lower ids), then its own that stay, in order. A merged
  // copy whose representative is on this rank is that point (used through it).
  std::vector<std::pair<int64_t, int64_t>> external; // (whole's id, local)
  for (std::size_t i = 0; i < n; ++i) {
    if (!used[i] || stays(i))
      continue;
    const Decision &d = mine[static_cast<std::size_t>(decided[i])];
    if (d.rep_rank != rank)
      external.emplace_back(global[i], static_cast<int64_t>(i));
    else
      used[static_cast<std::size_t>(d.rep_local)] = 1;
  }
  std::sort(external.begin(), external.end());
  std::size_t count = 0;
  for (std::size_t k = 0; k < external.size(); ++k)
    count += k == 0 || external[k].first != external[k - 1].first;
  for (std::size_t i = 0; i < n; ++i)
    count += used[i] && stays(i);
  UninitializedVector<int64_t> index(n);
  MeshInput &out = piece.input;
  piece.global_point.resize(count);
  piece.point_span.resize(count);
  out.points.resize(count);
  out.values.resize(count);
  std::size_t k = 0;
  auto place = [&](std::size_t i) {
    piece.global_point[k] = global[i];
    piece.point_span[k] = span_of(i);
    out.points[k] = m.points[i];
    out.values[k] = m.values[i];
    ++k;
  };
  for (std::size_t e = 0; e < external.size(); ++e) {
    if (e == 0 || external[e].first != external[e - 1].first)
      place(static_cast<std::size_t>(external[e].second));
    index[static_cast<std::size_t>(external[e].second)] = static_cast<int64_t>(k) - 1;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (used[i] && stays(i)) {
      index[i] = static_cast<int64_t>(k);
      place(i);
    }
  for (std::size_t i = 0; i < n; ++i)
    if (used[i] && !stays(i)) {
      const Decision &d = mine[static_cast<std::size_t>(decided[i])];
      if (d.rep_rank == rank)
        index[i] = index[static_cast<std::size_t>(d.rep_local)];
    }
  out.source = source;
  out.field_name = field_name;
  out.coordinate_precision = coordinate_precision;
  out.value_precision = value_precision;
  out.cell_offsets = std::move(m.cell_offsets);
  out.cell_degree = std::move(m.cell_degree);
  out.cell_kind = std::move(m.cell_kind);
  out.cell_nodes = std::move(m.cell_nodes);
  for (int64_t &q : out.cell_nodes)
    q = index[static_cast<std::size_t>(q)];
  int64_t triangles = static_cast<int64_t>(out.num_cells());
  if (!out.cell_kind.empty())
    for (std::size_t c = 0; c < out.num_cells(); ++c)
      triangles += is_quadrilateral(out.kind(c)) ? 1 : 0;
  piece.first_cell = exclusive_sum(comm, static_cast<int64_t>(out.num_cells()));
  in.first_triangle = exclusive_sum(comm, triangles);
  in.whole_cells = whole_cells;
  in.whole_points = whole_points;
  in.cells_split = with_kinds;
  in.source = source;
  in.field_name = field_name;
  if (rank == 0)
    in.fingerprint = InputFingerprint{whole_points, whole_cells, field_name, fingerprint};
  result.input = std::move(in);
  return result;
}

GllResampling resample_gll_share(RankInput &in, MPI_Comm comm) {
  std::string failure;
  int64_t counts[2] = {0, 0};
  try {
    const GllResampling g = resample_gll_cells(in.piece.input);
    counts[0] = g.cells;
    counts[1] = g.quadrilaterals;
  } catch (const std::exception &e) {
    failure = e.what();
  }
  agree_on_failure(failure, comm);
  MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPI_INT64_T, MPI_SUM, comm);
  in.read_whole = [read_whole = std::move(in.read_whole)] {
    MeshInput whole = read_whole();
    resample_gll_cells(whole);
    return whole;
  };
  return GllResampling{counts[0], counts[1]};
}

} // namespace hoct
