#include "distributed/distributed_arc_paths.hpp"

#include "distributed/mpi_exchange.hpp"
#include "util/byte_codec.hpp"
#include "util/stopwatch.hpp"

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

int64_t total_size(const std::vector<std::vector<std::byte>> &parts) {
  int64_t n = 0;
  for (const auto &p : parts)
    n += static_cast<int64_t>(p.size());
  return n;
}

} // namespace

std::vector<std::vector<Vec3>> distributed_arc_paths(MPI_Comm comm, PieceArcGraph &piece,
                                                     std::vector<ArcEnds> arcs, int threads,
                                                     ArcPathCounts *counts) {
  const Stopwatch clock;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  ArcPathCounts c;
  broadcast_array(comm, arcs);
  const std::size_t n = arcs.size();
  c.arcs = static_cast<int64_t>(n);
  c.bytes_sent += static_cast<int64_t>(n * sizeof(ArcEnds)) * (ranks - 1);
  std::vector<std::vector<Vec3>> paths(rank == 0 ? n : 0);

  // The nodes each rank holds with each other rank (their keys, once).
  piece.piece = rank;
  int64_t to_neighbours = 0; // this rank's bytes to the others, rank 0 excepted
  auto exchange = [&](const std::vector<std::vector<std::byte>> &out) {
    to_neighbours += total_size(out) - (rank == 0 ? 0 : static_cast<int64_t>(out[0].size()));
    return exchange_bytes(comm, out);
  };
  meet_neighbours(piece, exchange(border_offers(piece, ranks)));
  std::vector<int64_t> which(n);
  for (std::size_t i = 0; i < n; ++i)
    which[i] = static_cast<int64_t>(i);
  // The arcs of `which` a rank draws alone in `round`: the lowest rank that drew one sends it;
  // `which` keeps the others.
  auto local_step = [&](ArcRound round, int64_t visits) {
    std::vector<std::vector<Vec3>> local =
        draw_local_arcs(piece, arcs, which, round, visits, threads);
    std::vector<int> owner(which.size());
    for (std::size_t k = 0; k < which.size(); ++k)
      owner[k] = local[k].empty() ? ranks : rank;
    MPI_Allreduce(MPI_IN_PLACE, owner.data(), static_cast<int>(owner.size()), MPI_INT, MPI_MIN,
                  comm);
    std::vector<int64_t> arc, step, offset{0}, left;
    std::vector<Vec3> points;
    for (std::size_t k = 0; k < which.size(); ++k) {
      if (owner[k] == ranks)
        left.push_back(which[k]);
      if (owner[k] != rank)
        continue;
      arc.push_back(which[k]);
      step.push_back(0);
      points.insert(points.end(), local[k].begin(), local[k].end());
      offset.push_back(static_cast<int64_t>(points.size()));
    }
    ByteWriter w;
    w.array(arc);
    w.array(step);
    w.array(offset);
    w.array(points);
    const auto drawn = gather_bytes(comm, w.out);
    if (rank == 0) {
      c.bytes_received += total_size(drawn) - static_cast<int64_t>(drawn[0].size());
      join_stretches(drawn, paths);
    }
    c.local += static_cast<int64_t>(which.size() - left.size());
    which = std::move(left);
  };

  // The rounds: within the values, below, above (each first by the ranks alone, within the
  // values fully, below by a short search), then across ranks.
  for (int round = 0; round < kArcRounds && !which.empty(); ++round) {
    const auto r = static_cast<ArcRound>(round);
    if (r != ArcRound::Above)
      local_step(r, r == ArcRound::Band ? GeometricGraph::kMaxVisits : 1024);
    if (which.empty())
      break;
    const ArcComponents components = piece_components(piece, arcs, which, r);
    const auto labels = exchange(neighbour_labels(piece, components, arcs, which, r));
    const auto reports =
        gather_bytes(comm, component_report(piece, components, arcs, which, r, labels));
    std::vector<uint8_t> routed;
    std::vector<std::vector<std::byte>> parts;
    if (rank == 0) {
      c.component_bytes += total_size(reports) - static_cast<int64_t>(reports[0].size());
      c.bytes_received += total_size(reports) - static_cast<int64_t>(reports[0].size());
      for (const std::vector<Stretch> &s : route_arcs(reports, which, arcs, routed))
        parts.push_back(encode_stretches(s));
      c.bytes_sent += total_size(parts) - static_cast<int64_t>(parts[0].size());
    }
    const std::vector<Stretch> mine = decode_stretches(scatter_bytes(comm, parts));
    const auto drawn = gather_bytes(comm, draw_stretches(piece, arcs, mine, r));
    std::vector<int64_t> left;
    if (rank == 0) {
      c.bytes_received += total_size(drawn) - static_cast<int64_t>(drawn[0].size());
      join_stretches(drawn, paths);
      for (std::size_t k = 0; k < which.size(); ++k)
        if (routed[k])
          ++c.routed[round];
        else
          left.push_back(which[k]);
    }
    broadcast_array(comm, left);
    c.bytes_sent += static_cast<int64_t>(left.size() * sizeof(int64_t)) * (ranks - 1);
    which = std::move(left);
  }
  c.straight = static_cast<int64_t>(which.size());
  MPI_Reduce(&to_neighbours, &c.neighbour_bytes, 1, MPI_INT64_T, MPI_MAX, 0, comm);
  c.seconds = clock.seconds();
  if (counts && rank == 0)
    *counts = c;
  return paths;
}

} // namespace hoct
