#include "exact/piece_arcs.hpp"

#include "util/byte_codec.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace hoct {

void PieceArcGraph::index_keys() {
  by_key.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    by_key[i] = {keys[i], static_cast<int64_t>(i)};
  std::sort(by_key.begin(), by_key.end());
}

void PieceArcGraph::set_kept(int32_t number, const PieceTrees &trees, std::vector<int64_t> at) {
  const std::size_t n = trees.nodes.size();
  piece = number;
  ids = std::move(at);
  keys.resize(n);
  values.resize(n);
  spans.resize(n);
  shared.resize(n);
  chain_links.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const PieceNode &node = trees.nodes[k];
    keys[k] = node.key;
    values[k] = node.value;
    spans[k] = node.span;
    shared[k] = node.span[0] != number || node.span[1] != number; // other pieces may hold it
    if (k > 0 && keys[k] == keys[k - 1])
      chain_links.push_back({static_cast<int64_t>(k - 1), static_cast<int64_t>(k)});
  }
  join_parent = trees.join_parent;
  split_parent = trees.split_parent;
  index_keys();
}

int64_t PieceArcGraph::find(const NodeKey &key) const {
  const auto it = std::lower_bound(by_key.begin(), by_key.end(), std::pair(key, int64_t{-1}));
  return it != by_key.end() && it->first == key ? it->second : -1;
}

std::array<double, 2> round_values(const ArcEnds &arc, ArcRound round) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (round) {
  case ArcRound::Band:
    return {arc.lo, arc.hi};
  case ArcRound::Below:
    return {-inf, arc.hi};
  case ArcRound::Above:
    return {arc.lo, inf};
  case ArcRound::Anywhere:
    return {-inf, inf};
  }
  throw std::invalid_argument("round_values: no such round");
}

namespace {

// The graph nodes a parallel arc avoids, flagged in a search's scratch (one LowerLevels per
// scratch): only the flags set for the last arc are cleared, not a flag per node of the graph.
class LowerLevels {
public:
  // Flags the graph nodes of arc i's lower levels' paths in this piece; whether its group has
  // lower levels.
  bool flag(std::span<const ArcEnds> arcs, int64_t i, const ArcTrail *trail, int64_t graph_size,
            GeometricGraph::Search &s) {
    for (const int64_t v : flagged_)
      s.avoid[v] = 0;
    flagged_.clear();
    const ArcEnds &a = arcs[i];
    if (!trail || a.group < 0 || a.level == 0)
      return false;
    if (s.avoid.size() != static_cast<std::size_t>(graph_size))
      s.avoid.assign(static_cast<std::size_t>(graph_size), 0);
    for (const auto &[j, nodes] : *trail)
      if (arcs[j].group == a.group && arcs[j].level < a.level)
        for (const int64_t v : nodes)
          if (!s.avoid[v]) {
            s.avoid[v] = 1;
            flagged_.push_back(v);
          }
    return true;
  }

private:
  std::vector<int64_t> flagged_;
};

} // namespace

std::vector<std::vector<Vec3>>
draw_local_arcs(const PieceArcGraph &piece, std::span<const ArcEnds> arcs,
                std::span<const int64_t> which, ArcRound round, int64_t max_visits, int threads,
                const ArcTrail *trail, std::vector<std::vector<int64_t>> *nodes) {
  const int64_t n = static_cast<int64_t>(which.size());
  std::vector<std::vector<Vec3>> paths(which.size());
  if (nodes)
    nodes->assign(which.size(), {});
  if (!piece.graph || n == 0)
    return paths;
  const GeometricGraph &g = *piece.graph;
  const int used = threads_for(n, thread_count(threads), 16);
  std::vector<GeometricGraph::Search> scratch(static_cast<std::size_t>(used));
  std::vector<LowerLevels> lower(static_cast<std::size_t>(used));
  parallel_chunks(
      n, std::min<int64_t>(n, int64_t{used} * 256), used,
      [&](int64_t, int64_t begin, int64_t end, int worker) {
        GeometricGraph::Search &s = scratch[static_cast<std::size_t>(worker)];
        for (int64_t k = begin; k < end; ++k) {
          const ArcEnds &arc = arcs[which[k]];
          const int64_t a = piece.find(arc.lo_key), b = piece.find(arc.hi_key);
          if (a < 0 || b < 0)
            continue;
          lower[static_cast<std::size_t>(worker)].flag(arcs, which[k], trail, g.size(), s);
          const auto [lo, hi] = round_values(arc, round);
          std::vector<Vec3> p = g.band_path(piece.ids[a], piece.ids[b], lo, hi, max_visits, s);
          if (!s.nodes.empty()) {
            paths[k] = std::move(p);
            if (nodes)
              (*nodes)[k] = s.nodes;
          }
        }
      });
  return paths;
}

namespace {

// A stamped union-find over a piece's kept nodes, reset per arc in constant time.
class StampedSets {
public:
  explicit StampedSets(std::size_t n) : parent_(n), stamp_(n, 0) {}
  void reset() { ++generation_; }
  bool touched(int64_t x) const { return stamp_[x] == generation_; }
  int64_t find(int64_t x) {
    touch(x);
    while (parent_[x] != x) {
      touch(parent_[x]);
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(int64_t x, int64_t y) {
    x = find(x);
    y = find(y);
    if (x != y)
      parent_[std::max(x, y)] = std::min(x, y);
  }

private:
  void touch(int64_t x) {
    if (stamp_[x] != generation_) {
      stamp_[x] = generation_;
      parent_[x] = x;
    }
  }
  std::vector<int64_t> parent_;
  std::vector<uint32_t> stamp_;
  uint32_t generation_ = 1;
};

} // namespace

std::vector<std::vector<std::byte>> border_offers(const PieceArcGraph &piece, int pieces) {
  std::vector<std::vector<NodeKey>> keys(static_cast<std::size_t>(pieces));
  for (std::size_t x = 0; x < piece.ids.size(); ++x)
    if (piece.shared[x])
      for (int32_t r = std::max(piece.spans[x][0], 0); r <= piece.spans[x][1] && r < pieces; ++r)
        if (r != piece.piece)
          keys[r].push_back(piece.keys[x]);
  std::vector<std::vector<std::byte>> out;
  for (std::vector<NodeKey> &k : keys) {
    std::sort(k.begin(), k.end()); // (a point the piece's cut split: its copies' key once)
    k.erase(std::unique(k.begin(), k.end()), k.end());
    ByteWriter w;
    w.array(k);
    out.push_back(std::move(w.out));
  }
  return out;
}

void meet_neighbours(PieceArcGraph &piece, std::span<const std::vector<std::byte>> offers) {
  piece.common.assign(offers.size(), {});
  for (std::size_t r = 0; r < offers.size(); ++r) {
    ByteReader in(offers[r], "arc border offers");
    const std::vector<NodeKey> keys = in.array<NodeKey>();
    if (!in.done() ||
        std::adjacent_find(keys.begin(), keys.end(), std::greater_equal<>()) != keys.end())
      throw std::runtime_error("arc border offers: malformed");
    if (static_cast<int32_t>(r) == piece.piece)
      continue;
    // Both pieces hold these: each lists them in key order.
    for (const NodeKey &k : keys)
      if (const int64_t x = piece.find(k); x >= 0 && piece.shared[x])
        piece.common[r].push_back(x);
  }
}

ArcComponents piece_components(const PieceArcGraph &piece, std::span<const ArcEnds> arcs,
                               std::span<const int64_t> which, ArcRound round,
                               const ArcTrail *trail, int64_t max_visits) {
  ArcComponents out;
  out.label.resize(which.size());
  out.count.assign(which.size(), 0);
  out.ends.assign(which.size(), {-1, -1});
  GeometricGraph::Search scratch;
  LowerLevels lower;
  StampedSets sets(piece.ids.size());
  std::vector<int64_t> sources, graph_sources, label;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const ArcEnds &arc = arcs[which[k]];
    const auto [lo, hi] = round_values(arc, round);
    // The sources: the ends the piece holds, and its shared kept nodes within the values.
    const int64_t ends[2] = {piece.find(arc.lo_key), piece.find(arc.hi_key)};
    const bool avoiding =
        piece.graph && lower.flag(arcs, which[k], trail, piece.graph->size(), scratch);
    sources.clear();
    for (const int64_t x : ends)
      if (x >= 0)
        sources.push_back(x);
    const auto first = std::lower_bound(piece.values.begin(), piece.values.end(), lo),
               last = std::upper_bound(piece.values.begin(), piece.values.end(), hi);
    for (auto it = first; it != last; ++it) {
      const int64_t x = it - piece.values.begin();
      if (piece.shared[x] && x != ends[0] && x != ends[1] &&
          !(avoiding && scratch.avoid[piece.ids[x]]))
        sources.push_back(x);
    }
    if (sources.size() < 2 || !piece.graph)
      continue;
    label.assign(sources.size(), 0);
    if (round == ArcRound::Band || avoiding) {
      graph_sources.resize(sources.size());
      for (std::size_t s = 0; s < sources.size(); ++s)
        graph_sources[s] = piece.ids[sources[s]];
      if (!piece.graph->band_components(graph_sources, lo, hi, max_visits, scratch, label))
        continue;
    } else {
      // Below (above) the values: the kept join (split) tree joins two kept nodes where their
      // climbs up (down) it within the values meet (anywhere: their roots); the shared edges'
      // chains and the links of a cut point's copies join the rest.
      const bool below = round != ArcRound::Above;
      const std::vector<int64_t> &parent = below ? piece.join_parent : piece.split_parent;
      auto within = [&](int64_t x) { return piece.values[x] >= lo && piece.values[x] <= hi; };
      sets.reset();
      for (const int64_t x : sources)
        for (int64_t y = x; parent[y] >= 0 && within(parent[y]);) {
          const int64_t up = parent[y];
          const bool climbed = sets.touched(up); // then an earlier climb went on from there
          sets.unite(y, up);
          if (climbed)
            break;
          y = up;
        }
      for (const auto &[u, v] : piece.chain_links)
        if (within(u) && within(v))
          sets.unite(u, v);
      for (std::size_t s = 0; s < sources.size(); ++s)
        label[s] = sets.find(sources[s]);
    }
    // The components with two or more sources, numbered from 0; their nodes by kept index.
    std::vector<std::pair<int64_t, int64_t>> by_label(sources.size());
    for (std::size_t s = 0; s < sources.size(); ++s)
      by_label[s] = {label[s], static_cast<int64_t>(s)};
    std::sort(by_label.begin(), by_label.end());
    std::vector<std::pair<int64_t, int32_t>> &nodes = out.label[k];
    for (std::size_t s = 0; s < by_label.size();) {
      std::size_t e = s;
      while (e < by_label.size() && by_label[e].first == by_label[s].first)
        ++e;
      if (e - s >= 2) {
        const int32_t c = out.count[k]++;
        for (std::size_t j = s; j < e; ++j) {
          const int64_t x = sources[by_label[j].second];
          nodes.push_back({x, c});
          for (int end = 0; end < 2; ++end)
            if (x == ends[end])
              out.ends[k][end] = c;
        }
      }
      s = e;
    }
    std::sort(nodes.begin(), nodes.end());
  }
  return out;
}

namespace {

// The shared nodes `piece` holds with piece r, within [lo, hi], in key order, and each one's
// component (-1: none) for arc k.
template <class Visit>
void common_within(const PieceArcGraph &piece, const ArcComponents &components, std::size_t k,
                   std::size_t r, double lo, double hi, Visit visit) {
  const auto &nodes = components.label[k];
  for (const int64_t x : piece.common[r]) {
    if (piece.values[x] < lo || piece.values[x] > hi)
      continue;
    const auto it = std::lower_bound(nodes.begin(), nodes.end(), std::pair(x, int32_t{-1}));
    visit(x, it != nodes.end() && it->first == x ? it->second : int32_t{-1});
  }
}

} // namespace

std::vector<std::vector<std::byte>>
neighbour_labels(const PieceArcGraph &piece, const ArcComponents &components,
                 std::span<const ArcEnds> arcs, std::span<const int64_t> which, ArcRound round) {
  std::vector<std::vector<std::byte>> out(piece.common.size());
  for (std::size_t r = 0; r < piece.common.size(); ++r) {
    if (piece.common[r].empty())
      continue;
    std::vector<int32_t> labels;
    for (std::size_t k = 0; k < which.size(); ++k) {
      const auto [lo, hi] = round_values(arcs[which[k]], round);
      common_within(piece, components, k, r, lo, hi,
                    [&](int64_t, int32_t c) { labels.push_back(c); });
    }
    ByteWriter w;
    w.array(labels);
    out[r] = std::move(w.out);
  }
  return out;
}

std::vector<std::byte> component_report(const PieceArcGraph &piece, const ArcComponents &components,
                                        std::span<const ArcEnds> arcs,
                                        std::span<const int64_t> which, ArcRound round,
                                        std::span<const std::vector<std::byte>> labels) {
  std::vector<std::vector<int32_t>> theirs(labels.size());
  std::vector<std::size_t> at(labels.size(), 0);
  for (std::size_t r = 0; r < labels.size(); ++r) {
    if (labels[r].empty())
      continue;
    ByteReader in(labels[r], "arc component labels");
    theirs[r] = in.array<int32_t>();
    if (!in.done())
      throw std::runtime_error("arc component labels: malformed");
  }
  std::vector<int64_t> offset{0};
  std::vector<ComponentTouch> touches;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const auto [lo, hi] = round_values(arcs[which[k]], round);
    const std::size_t first = touches.size();
    for (std::size_t r = 0; r < piece.common.size() && r < labels.size(); ++r)
      common_within(piece, components, k, r, lo, hi, [&](int64_t x, int32_t mine) {
        if (at[r] >= theirs[r].size())
          throw std::runtime_error("arc component labels: fewer than the nodes shared");
        const int32_t other = theirs[r][at[r]++];
        if (mine >= 0 && other >= 0)
          touches.push_back({piece.keys[x], static_cast<int32_t>(r), other, mine, 0});
      });
    // One touch per pair of components.
    std::sort(touches.begin() + static_cast<std::ptrdiff_t>(first), touches.end(),
              [](const ComponentTouch &a, const ComponentTouch &b) {
                return std::tie(a.piece, a.theirs, a.mine, a.witness) <
                       std::tie(b.piece, b.theirs, b.mine, b.witness);
              });
    touches.erase(std::unique(touches.begin() + static_cast<std::ptrdiff_t>(first), touches.end(),
                              [](const ComponentTouch &a, const ComponentTouch &b) {
                                return a.piece == b.piece && a.theirs == b.theirs &&
                                       a.mine == b.mine;
                              }),
                  touches.end());
    offset.push_back(static_cast<int64_t>(touches.size()));
  }
  for (std::size_t r = 0; r < labels.size(); ++r)
    if (at[r] != theirs[r].size())
      throw std::runtime_error("arc component labels: more than the nodes shared");
  ByteWriter w;
  w.value<int32_t>(piece.piece);
  w.array(components.count);
  w.array(components.ends);
  w.array(offset);
  w.array(touches);
  return std::move(w.out);
}

std::vector<std::byte> draw_stretches(const PieceArcGraph &piece, std::span<const ArcEnds> arcs,
                                      std::span<const Stretch> stretches, ArcRound round,
                                      ArcTrail *trail) {
  std::vector<int64_t> arc, step, offset{0};
  std::vector<Vec3> points;
  GeometricGraph::Search s;
  LowerLevels lower;
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const Stretch &st : stretches) {
    const int64_t a = piece.find(st.from), b = piece.find(st.to);
    if (a < 0 || b < 0 || !piece.graph || st.arc < 0 || st.arc >= static_cast<int64_t>(arcs.size()))
      throw std::runtime_error("arc stretches: a stretch between nodes the piece does not hold");
    const GeometricGraph &g = *piece.graph;
    const int64_t x = piece.ids[a], y = piece.ids[b];
    const auto [lo, hi] = round_values(arcs[st.arc], round);
    // Within the round's values: a search (the piece's components joined the two there), below
    // or above first within a short search, then the forest's path that stays there (not
    // while avoiding nodes: the forests know nothing of them).
    const bool avoiding = lower.flag(arcs, st.arc, trail, g.size(), s);
    std::vector<Vec3> p;
    if (round == ArcRound::Band || round == ArcRound::Anywhere || avoiding) {
      p = g.band_path(x, y, lo, hi, std::numeric_limits<int64_t>::max(), s);
    } else {
      p = g.band_path(x, y, lo, hi, 1024, s);
      if (s.nodes.empty())
        p = round == ArcRound::Below ? g.minimax_path(x, y, inf, hi, s)
                                     : g.minimax_path(x, y, lo, -inf, s);
    }
    if (s.nodes.empty()) // not expected: the components said the piece joins them there
      p = g.band_path(x, y, -inf, inf, std::numeric_limits<int64_t>::max(), s);
    if (trail && arcs[st.arc].group >= 0) {
      std::vector<int64_t> &used = (*trail)[st.arc];
      used.insert(used.end(), s.nodes.begin(), s.nodes.end());
    }
    arc.push_back(st.arc);
    step.push_back(st.step);
    points.insert(points.end(), p.begin(), p.end());
    offset.push_back(static_cast<int64_t>(points.size()));
  }
  ByteWriter w;
  w.array(arc);
  w.array(step);
  w.array(offset);
  w.array(points);
  return std::move(w.out);
}

} // namespace hoct
