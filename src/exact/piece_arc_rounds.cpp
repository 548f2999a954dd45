#include "exact/piece_arc_rounds.hpp"

#include "util/byte_codec.hpp"
#include "util/stopwatch.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace hoct {
namespace {

using Bytes = PieceLinks::Bytes;

// The bytes of the pieces the root does not hold (what it received from other processes).
int64_t from_others(const std::vector<Bytes> &parts, std::span<PieceArcGraph *const> local) {
  int64_t n = 0;
  for (std::size_t p = 0; p < parts.size(); ++p)
    n += static_cast<int64_t>(parts[p].size());
  for (const PieceArcGraph *g : local)
    if (g->piece >= 0 && static_cast<std::size_t>(g->piece) < parts.size())
      n -= static_cast<int64_t>(parts[g->piece].size());
  return n;
}

// The bytes a process sends pieces it does not hold.
int64_t to_others(const std::vector<std::vector<Bytes>> &out,
                  std::span<PieceArcGraph *const> local) {
  int64_t n = 0;
  for (const auto &to : out)
    for (std::size_t p = 0; p < to.size(); ++p)
      if (std::none_of(local.begin(), local.end(),
                       [&](const PieceArcGraph *g) { return g->piece == static_cast<int>(p); }))
        n += static_cast<int64_t>(to[p].size());
  return n;
}

} // namespace

std::vector<ArcEnds> tree_arc_ends(const TreeResult &tree, std::span<const PieceNode> nodes,
                                   int32_t &groups) {
  std::vector<ArcEnds> arcs;
  for (const auto &[lo, hi] : tree.arcs) {
    const PieceNode &x = nodes[tree.nodes[lo].graph_node], &y = nodes[tree.nodes[hi].graph_node];
    arcs.push_back({x.key, y.key, x.value, y.value});
  }
  std::vector<std::size_t> by_ends(tree.arcs.size());
  std::iota(by_ends.begin(), by_ends.end(), std::size_t{0});
  std::stable_sort(by_ends.begin(), by_ends.end(),
                   [&](std::size_t x, std::size_t y) { return tree.arcs[x] < tree.arcs[y]; });
  for (std::size_t k = 1; k < by_ends.size(); ++k)
    if (tree.arcs[by_ends[k]] == tree.arcs[by_ends[k - 1]]) {
      ArcEnds &before = arcs[by_ends[k - 1]], &a = arcs[by_ends[k]];
      if (before.group < 0)
        before.group = groups++;
      a.group = before.group;
      a.level = before.level + 1;
    }
  return arcs;
}

std::vector<std::vector<Bytes>> InProcessLinks::exchange(std::vector<std::vector<Bytes>> out) {
  std::vector<std::vector<Bytes>> in(out.size(), std::vector<Bytes>(out.size()));
  for (std::size_t from = 0; from < out.size(); ++from)
    for (std::size_t to = 0; to < out[from].size() && to < out.size(); ++to)
      in[to][from] = std::move(out[from][to]);
  return in;
}

std::vector<int32_t> InProcessLinks::least(std::vector<std::vector<int32_t>> own) {
  std::vector<int32_t> m = own.empty() ? std::vector<int32_t>{} : own[0];
  for (const auto &v : own)
    for (std::size_t i = 0; i < m.size(); ++i)
      m[i] = std::min(m[i], v[i]);
  return m;
}

std::vector<std::vector<Vec3>> draw_arcs_by_pieces(std::span<PieceArcGraph *const> local,
                                                   std::span<const ArcEnds> arcs, PieceLinks &links,
                                                   int threads, ArcPathCounts *counts,
                                                   std::vector<ArcDrawn> *how) {
  const Stopwatch clock;
  const int pieces = links.pieces();
  const bool root = links.root();
  const std::size_t n = arcs.size(), h = local.size();
  ArcPathCounts c;
  c.arcs = static_cast<int64_t>(n);
  std::vector<std::vector<Vec3>> paths(root ? n : 0);
  std::vector<ArcDrawn> drawn_how(root ? n : 0);
  int64_t to_neighbours = 0;
  auto exchange = [&](std::vector<std::vector<Bytes>> out) {
    to_neighbours += to_others(out, local);
    return links.exchange(std::move(out));
  };
  auto gather = [&](std::vector<Bytes> own, bool reports) {
    std::vector<Bytes> all = links.gather(std::move(own));
    if (root) {
      const int64_t b = from_others(all, local);
      c.bytes_received += b;
      if (reports)
        c.component_bytes += b;
    }
    return all;
  };

  // Once: the nodes each piece holds with each other piece.
  {
    std::vector<std::vector<Bytes>> offers;
    for (const PieceArcGraph *p : local)
      offers.push_back(border_offers(*p, pieces));
    const auto offered = exchange(std::move(offers));
    for (std::size_t l = 0; l < h; ++l)
      meet_neighbours(*local[l], offered[l]);
  }
  std::vector<ArcTrail> trails(h);
  int32_t levels = 1;
  for (const ArcEnds &a : arcs)
    levels = std::max(levels, a.level + 1);

  for (int32_t level = 0; level < levels; ++level) {
    std::vector<int64_t> which;
    for (std::size_t i = 0; i < n; ++i)
      if (arcs[i].level == level)
        which.push_back(static_cast<int64_t>(i));
    // The arcs of `which` a piece draws alone in `round`: the lowest piece that drew one sends
    // it; `which` keeps the others.
    auto local_step = [&](ArcRound round, int64_t visits) {
      std::vector<std::vector<std::vector<Vec3>>> drawn(h);
      std::vector<std::vector<std::vector<int64_t>>> nodes(h);
      std::vector<std::vector<int32_t>> owner(h);
      for (std::size_t l = 0; l < h; ++l) {
        drawn[l] =
            draw_local_arcs(*local[l], arcs, which, round, visits, threads, &trails[l], &nodes[l]);
        owner[l].resize(which.size());
        for (std::size_t k = 0; k < which.size(); ++k)
          owner[l][k] = drawn[l][k].empty() ? pieces : local[l]->piece;
      }
      const std::vector<int32_t> first = links.least(owner);
      std::vector<Bytes> own(h);
      for (std::size_t l = 0; l < h; ++l) {
        std::vector<int64_t> arc, step, offset{0};
        std::vector<Vec3> points;
        for (std::size_t k = 0; k < which.size(); ++k) {
          if (first[k] != local[l]->piece)
            continue;
          arc.push_back(which[k]);
          step.push_back(0);
          points.insert(points.end(), drawn[l][k].begin(), drawn[l][k].end());
          offset.push_back(static_cast<int64_t>(points.size()));
          if (arcs[which[k]].group >= 0)
            trails[l][which[k]] = std::move(nodes[l][k]);
        }
        ByteWriter w;
        w.array(arc);
        w.array(step);
        w.array(offset);
        w.array(points);
        own[l] = std::move(w.out);
      }
      const std::vector<Bytes> all = gather(std::move(own), false);
      if (root)
        join_stretches(all, paths);
      std::vector<int64_t> left;
      for (std::size_t k = 0; k < which.size(); ++k)
        if (first[k] == pieces)
          left.push_back(which[k]);
        else if (root)
          drawn_how[which[k]] = {static_cast<int32_t>(round), false};
      c.local += static_cast<int64_t>(which.size() - left.size());
      which = std::move(left);
    };

    // The rounds: within the values, below, above, anywhere (the first two first by the pieces
    // alone: within the values fully, below by a short search, as one process's first pass),
    // then across pieces.
    for (int round = 0; round < kArcRounds && !which.empty(); ++round) {
      const auto r = static_cast<ArcRound>(round);
      if (r == ArcRound::Band || r == ArcRound::Below)
        local_step(r, r == ArcRound::Band ? GeometricGraph::kMaxVisits : 1024);
      if (which.empty())
        break;
      std::vector<ArcComponents> components(h);
      std::vector<std::vector<Bytes>> labels(h);
      for (std::size_t l = 0; l < h; ++l) {
        components[l] = piece_components(*local[l], arcs, which, r, &trails[l]);
        labels[l] = neighbour_labels(*local[l], components[l], arcs, which, r);
      }
      const auto received = exchange(std::move(labels));
      std::vector<Bytes> reports(h);
      for (std::size_t l = 0; l < h; ++l)
        reports[l] = component_report(*local[l], components[l], arcs, which, r, received[l]);
      const std::vector<Bytes> all_reports = gather(std::move(reports), true);
      std::vector<uint8_t> routed;
      std::vector<Bytes> parts;
      if (root) {
        for (const std::vector<Stretch> &s : route_arcs(all_reports, which, arcs, routed))
          parts.push_back(encode_stretches(s));
        c.bytes_sent += from_others(parts, local);
      }
      const std::vector<Bytes> mine = links.scatter(std::move(parts));
      std::vector<Bytes> drawn(h);
      for (std::size_t l = 0; l < h; ++l)
        drawn[l] = draw_stretches(*local[l], arcs, decode_stretches(mine[l]), r, &trails[l]);
      const std::vector<Bytes> all_drawn = gather(std::move(drawn), false);
      std::vector<int64_t> left;
      if (root) {
        join_stretches(all_drawn, paths);
        for (std::size_t k = 0; k < which.size(); ++k)
          if (routed[k]) {
            ++c.routed[round];
            drawn_how[which[k]] = {round, true};
          } else
            left.push_back(which[k]);
      }
      links.broadcast(left);
      which = std::move(left);
    }
    c.straight += static_cast<int64_t>(which.size());
  }
  c.neighbour_bytes = links.largest(to_neighbours);
  c.seconds = clock.seconds();
  if (counts && root)
    *counts = c;
  if (how && root)
    *how = std::move(drawn_how);
  return paths;
}

} // namespace hoct
