#include "exact/piece_arcs.hpp"

#include "util/byte_codec.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>
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
  }
  throw std::invalid_argument("round_values: no such round");
}

std::vector<std::vector<Vec3>> draw_local_arcs(const PieceArcGraph &piece,
                                               std::span<const ArcEnds> arcs,
                                               std::span<const int64_t> which, ArcRound round,
                                               int64_t max_visits, int threads) {
  const int64_t n = static_cast<int64_t>(which.size());
  std::vector<std::vector<Vec3>> paths(which.size());
  if (!piece.graph || n == 0)
    return paths;
  const int used = threads_for(n, thread_count(threads), 16);
  std::vector<GeometricGraph::Search> scratch(static_cast<std::size_t>(used));
  parallel_chunks(n, std::min<int64_t>(n, int64_t{used} * 256), used,
                  [&](int64_t, int64_t begin, int64_t end, int worker) {
                    GeometricGraph::Search &s = scratch[static_cast<std::size_t>(worker)];
                    for (int64_t k = begin; k < end; ++k) {
                      const ArcEnds &arc = arcs[which[k]];
                      const int64_t a = piece.find(arc.lo_key), b = piece.find(arc.hi_key);
                      if (a < 0 || b < 0)
                        continue;
                      const auto [lo, hi] = round_values(arc, round);
                      std::vector<Vec3> p =
                          piece.graph->band_path(piece.ids[a], piece.ids[b], lo, hi, max_visits, s);
                      if (!s.nodes.empty())
                        paths[k] = std::move(p);
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

std::vector<std::byte> piece_components(const PieceArcGraph &piece, std::span<const ArcEnds> arcs,
                                        std::span<const int64_t> which, ArcRound round,
                                        int64_t max_visits) {
  // Per component: its arc, and its keys (components[k] .. components[k + 1]).
  std::vector<int64_t> arc_of, offset{0};
  std::vector<NodeKey> keys;
  GeometricGraph::Search scratch;
  StampedSets sets(piece.ids.size());
  std::vector<int64_t> sources, graph_sources, label;
  for (const int64_t i : which) {
    const ArcEnds &arc = arcs[i];
    const auto [lo, hi] = round_values(arc, round);
    // The sources: the ends the piece holds, and its shared kept nodes within the values.
    sources.clear();
    for (const NodeKey &k : {arc.lo_key, arc.hi_key})
      if (const int64_t x = piece.find(k); x >= 0)
        sources.push_back(x);
    const auto first = std::lower_bound(piece.values.begin(), piece.values.end(), lo),
               last = std::upper_bound(piece.values.begin(), piece.values.end(), hi);
    for (auto it = first; it != last; ++it) {
      const int64_t x = it - piece.values.begin();
      if (piece.shared[x] && (sources.empty() || x != sources[0]) &&
          (sources.size() < 2 || x != sources[1]))
        sources.push_back(x);
    }
    if (sources.size() < 2 || !piece.graph)
      continue;
    label.assign(sources.size(), 0);
    if (round == ArcRound::Band) {
      graph_sources.resize(sources.size());
      for (std::size_t s = 0; s < sources.size(); ++s)
        graph_sources[s] = piece.ids[sources[s]];
      if (!piece.graph->band_components(graph_sources, lo, hi, max_visits, scratch, label))
        continue;
    } else {
      // Below (above) the values: the kept join (split) tree joins two kept nodes where their
      // climbs up (down) it within the values meet; the shared edges' chains join the rest.
      const bool below = round == ArcRound::Below;
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
    // Components with two or more sources, each listed once.
    std::vector<std::pair<int64_t, int64_t>> by_label(sources.size());
    for (std::size_t s = 0; s < sources.size(); ++s)
      by_label[s] = {label[s], static_cast<int64_t>(s)};
    std::sort(by_label.begin(), by_label.end());
    for (std::size_t s = 0; s < by_label.size();) {
      std::size_t e = s;
      while (e < by_label.size() && by_label[e].first == by_label[s].first)
        ++e;
      if (e - s >= 2) {
        arc_of.push_back(i);
        for (std::size_t k = s; k < e; ++k)
          keys.push_back(piece.keys[sources[by_label[k].second]]);
        offset.push_back(static_cast<int64_t>(keys.size()));
      }
      s = e;
    }
  }
  ByteWriter w;
  w.array(arc_of);
  w.array(offset);
  w.array(keys);
  return std::move(w.out);
}

std::vector<std::vector<Stretch>> route_arcs(std::span<const std::vector<std::byte>> components,
                                             std::span<const int64_t> which,
                                             std::span<const ArcEnds> arcs,
                                             std::vector<uint8_t> &routed) {
  // Every piece's components, by the arc's place in `which` (ascending).
  struct Component {
    int32_t piece;
    std::vector<NodeKey> keys;
  };
  std::vector<std::vector<Component>> of(which.size());
  for (std::size_t p = 0; p < components.size(); ++p) {
    ByteReader r(components[p], "arc components");
    const auto arc_of = r.array<int64_t>();
    const auto offset = r.array<int64_t>();
    const auto keys = r.array<NodeKey>();
    if (!r.done() || offset.size() != arc_of.size() + 1 || offset.front() != 0 ||
        offset.back() != static_cast<int64_t>(keys.size()))
      throw std::runtime_error("arc components: malformed");
    for (std::size_t c = 0; c < arc_of.size(); ++c) {
      const auto at = std::lower_bound(which.begin(), which.end(), arc_of[c]);
      if (at == which.end() || *at != arc_of[c] || offset[c + 1] < offset[c])
        throw std::runtime_error("arc components: an arc not asked for");
      of[static_cast<std::size_t>(at - which.begin())].push_back(
          {static_cast<int32_t>(p),
           std::vector<NodeKey>(keys.begin() + offset[c], keys.begin() + offset[c + 1])});
    }
  }
  std::vector<std::vector<Stretch>> out(components.size());
  routed.assign(which.size(), 0);
  for (std::size_t k = 0; k < which.size(); ++k) {
    const std::vector<Component> &comps = of[k];
    // A graph of keys (0 .. K) and components (K ..): breadth-first from the lower end.
    std::vector<NodeKey> names;
    for (const Component &c : comps)
      names.insert(names.end(), c.keys.begin(), c.keys.end());
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    auto name = [&](const NodeKey &key) {
      const auto it = std::lower_bound(names.begin(), names.end(), key);
      return it != names.end() && *it == key ? static_cast<int64_t>(it - names.begin()) : -1;
    };
    const ArcEnds &arc = arcs[which[k]];
    const int64_t from = name(arc.lo_key), to = name(arc.hi_key);
    if (from < 0 || to < 0)
      continue;
    const int64_t K = static_cast<int64_t>(names.size());
    std::vector<std::vector<int64_t>> key_comps(names.size());
    for (std::size_t c = 0; c < comps.size(); ++c)
      for (const NodeKey &key : comps[c].keys)
        key_comps[name(key)].push_back(static_cast<int64_t>(c));
    std::vector<int64_t> back(names.size() + comps.size(), -2);
    std::vector<int64_t> queue{from};
    back[from] = -1;
    for (std::size_t h = 0; h < queue.size() && back[to] == -2; ++h) {
      const int64_t v = queue[h];
      if (v < K) {
        for (const int64_t c : key_comps[v])
          if (back[K + c] == -2) {
            back[K + c] = v;
            queue.push_back(K + c);
          }
      } else {
        for (const NodeKey &key : comps[v - K].keys)
          if (const int64_t x = name(key); back[x] == -2) {
            back[x] = v;
            queue.push_back(x);
          }
      }
    }
    if (back[to] == -2)
      continue;
    // The route back from the upper end: key, component, key, ...
    std::vector<int64_t> route;
    for (int64_t v = to; v != -1; v = back[v])
      route.push_back(v);
    std::reverse(route.begin(), route.end());
    const int32_t steps = static_cast<int32_t>(route.size() / 2);
    for (int32_t s = 0; s < steps; ++s) {
      const Component &c = comps[route[2 * s + 1] - K];
      out[c.piece].push_back({which[k], s, steps, names[route[2 * s]], names[route[2 * s + 2]]});
    }
    routed[k] = 1;
  }
  return out;
}

std::vector<std::byte> draw_stretches(const PieceArcGraph &piece, std::span<const ArcEnds> arcs,
                                      std::span<const Stretch> stretches, ArcRound round) {
  std::vector<int64_t> arc, step, offset{0};
  std::vector<Vec3> points;
  GeometricGraph::Search s;
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const Stretch &st : stretches) {
    const int64_t a = piece.find(st.from), b = piece.find(st.to);
    if (a < 0 || b < 0 || !piece.graph || st.arc < 0 || st.arc >= static_cast<int64_t>(arcs.size()))
      throw std::runtime_error("arc stretches: a stretch between nodes the piece does not hold");
    const GeometricGraph &g = *piece.graph;
    const int64_t x = piece.ids[a], y = piece.ids[b];
    const auto [lo, hi] = round_values(arcs[st.arc], round);
    // Within the round's values: a search (the piece's components joined the two there), below
    // or above first within a short search, then the forest's path that stays there.
    std::vector<Vec3> p;
    if (round == ArcRound::Band) {
      p = g.band_path(x, y, lo, hi, std::numeric_limits<int64_t>::max(), s);
    } else {
      p = g.band_path(x, y, lo, hi, 1024, s);
      if (s.nodes.empty())
        p = round == ArcRound::Below ? g.minimax_path(x, y, inf, hi, s)
                                     : g.minimax_path(x, y, lo, -inf, s);
    }
    if (s.nodes.empty()) // not expected: the components said the piece joins them there
      p = g.band_path(x, y, -inf, inf, std::numeric_limits<int64_t>::max(), s);
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

void join_stretches(std::span<const std::vector<std::byte>> drawn,
                    std::vector<std::vector<Vec3>> &paths) {
  struct Piece {
    int64_t arc, step;
    const Vec3 *begin, *end;
  };
  std::vector<std::vector<Vec3>> kept;
  std::vector<Piece> all;
  for (const std::vector<std::byte> &bytes : drawn) {
    ByteReader r(bytes, "arc stretches");
    const auto arc = r.array<int64_t>();
    const auto step = r.array<int64_t>();
    const auto offset = r.array<int64_t>();
    kept.push_back(r.array<Vec3>());
    const std::vector<Vec3> &points = kept.back();
    if (!r.done() || step.size() != arc.size() || offset.size() != arc.size() + 1 ||
        offset.front() != 0 || offset.back() != static_cast<int64_t>(points.size()))
      throw std::runtime_error("arc stretches: malformed");
    for (std::size_t i = 0; i < arc.size(); ++i) {
      if (arc[i] < 0 || arc[i] >= static_cast<int64_t>(paths.size()) || offset[i + 1] < offset[i])
        throw std::runtime_error("arc stretches: malformed");
      all.push_back({arc[i], step[i], points.data() + offset[i], points.data() + offset[i + 1]});
    }
  }
  std::sort(all.begin(), all.end(), [](const Piece &x, const Piece &y) {
    return std::tie(x.arc, x.step) < std::tie(y.arc, y.step);
  });
  for (const Piece &p : all) {
    std::vector<Vec3> &path = paths[p.arc];
    // Each stretch after the first starts where the one before ended (a shared node, placed
    // by either piece): that point once.
    path.insert(path.end(), p.begin + (path.empty() ? 0 : 1), p.end);
  }
}

std::vector<std::byte> encode_stretches(std::span<const Stretch> stretches) {
  ByteWriter w;
  w.array(std::vector<Stretch>(stretches.begin(), stretches.end()));
  return std::move(w.out);
}

std::vector<Stretch> decode_stretches(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "arc stretches");
  std::vector<Stretch> s = r.array<Stretch>();
  if (!r.done())
    throw std::runtime_error("arc stretches: trailing bytes");
  return s;
}

} // namespace hoct
