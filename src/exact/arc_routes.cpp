#include "exact/arc_routes.hpp"

#include "util/byte_codec.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace hoct {

std::vector<std::vector<Stretch>> route_arcs(std::span<const std::vector<std::byte>> reports,
                                             std::span<const int64_t> which,
                                             std::span<const ArcEnds> arcs,
                                             std::vector<uint8_t> &routed) {
  struct Report {
    std::vector<int32_t> count;
    std::vector<std::array<int32_t, 2>> ends;
    std::vector<int64_t> offset;
    std::vector<ComponentTouch> touches;
  };
  const std::size_t pieces = reports.size();
  std::vector<Report> rep(pieces);
  for (std::size_t p = 0; p < pieces; ++p) {
    ByteReader in(reports[p], "arc component reports");
    Report &r = rep[p];
    const int32_t number = in.value<int32_t>();
    r.count = in.array<int32_t>();
    r.ends = in.array<std::array<int32_t, 2>>();
    r.offset = in.array<int64_t>();
    r.touches = in.array<ComponentTouch>();
    bool ok = in.done() && number == static_cast<int32_t>(p) && r.count.size() == which.size() &&
              r.ends.size() == which.size() && r.offset.size() == which.size() + 1 &&
              r.offset.front() == 0 && r.offset.back() == static_cast<int64_t>(r.touches.size());
    for (std::size_t k = 0; ok && k < which.size(); ++k) {
      ok = r.count[k] >= 0 && r.offset[k] <= r.offset[k + 1] && r.ends[k][0] < r.count[k] &&
           r.ends[k][1] < r.count[k];
    }
    if (!ok)
      throw std::runtime_error("arc component reports: malformed");
  }
  for (std::size_t p = 0; p < pieces; ++p) // touches name components that exist
    for (std::size_t k = 0; k < which.size(); ++k)
      for (int64_t t = rep[p].offset[k]; t < rep[p].offset[k + 1]; ++t) {
        const ComponentTouch &x = rep[p].touches[t];
        if (x.piece < 0 || static_cast<std::size_t>(x.piece) >= pieces || x.mine < 0 ||
            x.mine >= rep[p].count[k] || x.theirs < 0 || x.theirs >= rep[x.piece].count[k])
          throw std::runtime_error("arc component reports: a touch of no component");
      }
  std::vector<std::vector<Stretch>> out(pieces);
  routed.assign(which.size(), 0);
  std::vector<int64_t> first(pieces + 1);
  for (std::size_t k = 0; k < which.size(); ++k) {
    // The components of all pieces as one graph: piece p's c is first[p] + c.
    for (std::size_t p = 0; p < pieces; ++p)
      first[p + 1] = first[p] + rep[p].count[k];
    const int64_t n = first[pieces];
    std::vector<int64_t> piece_of(static_cast<std::size_t>(n));
    for (std::size_t p = 0; p < pieces; ++p)
      for (int64_t v = first[p]; v < first[p + 1]; ++v)
        piece_of[v] = static_cast<int64_t>(p);
    std::vector<std::vector<std::pair<int64_t, NodeKey>>> next(static_cast<std::size_t>(n));
    for (std::size_t p = 0; p < pieces; ++p)
      for (int64_t t = rep[p].offset[k]; t < rep[p].offset[k + 1]; ++t) {
        const ComponentTouch &x = rep[p].touches[t];
        const int64_t a = first[p] + x.mine, b = first[x.piece] + x.theirs;
        next[a].push_back({b, x.witness});
        next[b].push_back({a, x.witness});
      }
    // Breadth-first from every component with the lower end to one with the upper end.
    std::vector<int64_t> back(static_cast<std::size_t>(n), -2), queue;
    std::vector<NodeKey> via(static_cast<std::size_t>(n));
    for (std::size_t p = 0; p < pieces; ++p)
      if (const int32_t c = rep[p].ends[k][0]; c >= 0) {
        back[first[p] + c] = -1;
        queue.push_back(first[p] + c);
      }
    int64_t goal = -1;
    for (std::size_t h = 0; h < queue.size() && goal < 0; ++h) {
      const int64_t v = queue[h];
      if (rep[piece_of[v]].ends[k][1] == v - first[piece_of[v]]) {
        goal = v;
        break;
      }
      for (const auto &[w, key] : next[v])
        if (back[w] == -2) {
          back[w] = v;
          via[w] = key;
          queue.push_back(w);
        }
    }
    if (goal < 0)
      continue;
    std::vector<int64_t> route;
    for (int64_t v = goal; v != -1; v = back[v])
      route.push_back(v);
    std::reverse(route.begin(), route.end());
    const ArcEnds &arc = arcs[which[k]];
    const int32_t steps = static_cast<int32_t>(route.size());
    for (int32_t s = 0; s < steps; ++s) {
      const int64_t v = route[s];
      const NodeKey from = s == 0 ? arc.lo_key : via[v],
                    to = s + 1 == steps ? arc.hi_key : via[route[s + 1]];
      out[piece_of[v]].push_back({which[k], s, steps, from, to});
    }
    routed[k] = 1;
  }
  return out;
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
