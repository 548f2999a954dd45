#include "tree/geometric_graph.hpp"

#include "tree/node_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hoct {

void GeometricGraph::reserve(std::size_t edges, std::size_t points) {
  ends_.reserve(edges);
  point_offset_.reserve(edges + 1);
  points_.reserve(points);
}

void GeometricGraph::add_edge(int64_t a, int64_t b, const Vec3 *interior, std::size_t count) {
  if (a == b)
    return;
  ends_.push_back({a, b});
  points_.insert(points_.end(), interior, interior + count);
  point_offset_.push_back(static_cast<int64_t>(points_.size()));
}

void GeometricGraph::set_edges(std::vector<std::array<int64_t, 2>> ends,
                               std::vector<int64_t> point_offset,
                               UninitializedVector<Vec3> points) {
  ends_ = std::move(ends);
  point_offset_ = std::move(point_offset);
  points_ = std::move(points);
}

void GeometricGraph::finish() {
  forest_ = std::make_shared<LazyForest>();
  const int64_t n = size();
  offset_.assign(n + 1, 0);
  for (const auto &e : ends_) {
    if (e[0] == e[1])
      continue;
    ++offset_[e[0] + 1];
    ++offset_[e[1] + 1];
  }
  std::partial_sum(offset_.begin(), offset_.end(), offset_.begin());
  adj_.resize(offset_[n]);
  adj_edge_.resize(offset_[n]);
  std::vector<int64_t> fill(offset_.begin(), offset_.end() - 1);
  for (std::size_t i = 0; i < ends_.size(); ++i) {
    const auto &e = ends_[i];
    if (e[0] == e[1])
      continue;
    adj_[fill[e[0]]] = e[1];
    adj_edge_[fill[e[0]]++] = static_cast<int64_t>(i);
    adj_[fill[e[1]]] = e[0];
    adj_edge_[fill[e[1]]++] = static_cast<int64_t>(i);
  }
}

std::vector<Vec3> GeometricGraph::path(int64_t a, int64_t b, Search &scratch,
                                       int64_t below_visits) const {
  const double lo = std::min(value_[a], value_[b]), hi = std::max(value_[a], value_[b]);
  std::vector<Vec3> p = search(a, b, lo, hi, kMaxVisits, scratch);
  return scratch.nodes.empty() ? beyond_path(a, b, scratch, below_visits) : p;
}

std::vector<Vec3> GeometricGraph::near_path(int64_t a, int64_t b, Search &scratch,
                                            int64_t below_visits) const {
  const double lo = std::min(value_[a], value_[b]), hi = std::max(value_[a], value_[b]);
  std::vector<Vec3> p = search(a, b, lo, hi, kMaxVisits, scratch);
  // No path within the arc's values (the contours of a narrow arc may cross no node of it):
  // below the upper end's value, where the join tree connects the two ends of an arc.
  if (scratch.nodes.empty() && below_visits > 0)
    p = search(a, b, -INFINITY, hi, below_visits, scratch);
  return p;
}

std::vector<Vec3> GeometricGraph::beyond_path(int64_t a, int64_t b, Search &scratch,
                                              int64_t below_visits) const {
  const double lo = std::min(value_[a], value_[b]), hi = std::max(value_[a], value_[b]);
  std::vector<Vec3> p;
  scratch.nodes.clear();
  if (below_visits > 0)
    p = search(a, b, -INFINITY, hi, below_visits, scratch);
  // On a field with many features, whose sublevel sets wind through much of the surface, a
  // search below may visit most of it: the forests' paths instead, below the upper end's value
  // or above the lower end's (where the split tree connects the ends), found without a search;
  // then any path on the surface rather than a chord through it.
  if (scratch.nodes.empty() && scratch.avoid.empty())
    p = forest_path(a, b, lo, hi, scratch);
  if (scratch.nodes.empty())
    p = search(a, b, -INFINITY, INFINITY, kMaxVisits, scratch);
  return p;
}

std::vector<Vec3> GeometricGraph::forest_path(int64_t a, int64_t b, double lo, double hi,
                                              Search &s) const {
  std::call_once(forest_->built, [&] {
    const std::vector<int64_t> order = ascending_order(value_);
    using Side = SublevelForest::Side;
    forest_->sublevel = SublevelForest(Side::Sublevel, order, offset_, adj_, adj_edge_);
    forest_->superlevel = SublevelForest(Side::Superlevel, order, offset_, adj_, adj_edge_);
  });
  std::vector<Vec3> out;
  std::vector<int64_t> edges, up_nodes, up_edges;
  const bool below =
      forest_->sublevel.path(a, b, s.nodes, edges) &&
      std::none_of(s.nodes.begin(), s.nodes.end(), [&](int64_t v) { return value_[v] > hi; });
  const bool above =
      forest_->superlevel.path(a, b, up_nodes, up_edges) &&
      std::none_of(up_nodes.begin(), up_nodes.end(), [&](int64_t v) { return value_[v] < lo; });
  if (above && (!below || up_nodes.size() < s.nodes.size())) {
    s.nodes = std::move(up_nodes);
    edges = std::move(up_edges);
  } else if (!below) {
    s.nodes.clear();
    return out;
  }
  // The forest's paths wander (they follow the order in which the sublevel sets merged): cut
  // short from each node to the furthest later node of the path it has an edge to, a
  // subsequence of the path's nodes (within its values), each step an edge of the graph.
  if (s.stamp.size() != value_.size() || s.generation >= UINT32_MAX - 2) {
    s.stamp.assign(value_.size(), 0);
    s.from.assign(value_.size(), -1);
    s.generation = 0;
  }
  s.generation += 2;
  const std::vector<int64_t> &nodes = s.nodes;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    s.stamp[nodes[i]] = s.generation;
    s.from[nodes[i]] = static_cast<int64_t>(i);
  }
  out.push_back(position(a));
  std::vector<int64_t> kept = {a};
  for (int64_t i = 0, last = static_cast<int64_t>(nodes.size()) - 1; i < last;) {
    int64_t best = i + 1, edge = edges[i];
    for (int64_t k = offset_[nodes[i]]; k < offset_[nodes[i] + 1]; ++k) {
      const int64_t w = adj_[k];
      if (s.stamp[w] == s.generation && s.from[w] > best) {
        best = s.from[w];
        edge = adj_edge_[k];
      }
    }
    append_edge(edge, nodes[i], out);
    kept.push_back(nodes[best]);
    i = best;
  }
  s.nodes = std::move(kept);
  return out;
}

int64_t GeometricGraph::append_edge(int64_t e, int64_t u, std::vector<Vec3> &out) const {
  const auto &ends = ends_[e];
  const bool forward = ends[0] == u; // the points run ends[0] -> ends[1]
  const int64_t placed = geometry_ ? geometry_->edges() : 0;
  if (e < placed)
    geometry_->edge_points(e, forward, out);
  else if (forward)
    for (int64_t i = point_offset_[e - placed]; i < point_offset_[e - placed + 1]; ++i)
      out.push_back(points_[i]);
  else
    for (int64_t i = point_offset_[e - placed + 1] - 1; i >= point_offset_[e - placed]; --i)
      out.push_back(points_[i]);
  const int64_t next = forward ? ends[1] : ends[0];
  out.push_back(position(next));
  return next;
}

bool GeometricGraph::band_components(std::span<const int64_t> sources, double lo, double hi,
                                     int64_t max_visits, Search &s,
                                     std::vector<int64_t> &label) const {
  // One breadth-first search per source not reached yet; a node's stamp is the generation of
  // this call, `from` the source whose search reached it.
  if (s.stamp.size() != value_.size() || s.generation >= UINT32_MAX - 2) {
    s.stamp.assign(value_.size(), 0);
    s.from.assign(value_.size(), -1);
    s.generation = 0;
  }
  s.generation += 2;
  const uint32_t seen = s.generation;
  label.assign(sources.size(), -1);
  int64_t visits = 0;
  std::vector<int64_t> &queue = s.queue;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const int64_t v0 = sources[i];
    if (s.stamp[v0] == seen) {
      label[i] = s.from[v0];
      continue;
    }
    label[i] = static_cast<int64_t>(i);
    s.stamp[v0] = seen;
    s.from[v0] = static_cast<int64_t>(i);
    queue.assign(1, v0);
    for (std::size_t h = 0; h < queue.size(); ++h) {
      if (++visits > max_visits)
        return false;
      const int64_t v = queue[h];
      for (int64_t k = offset_[v]; k < offset_[v + 1]; ++k) {
        const int64_t w = adj_[k];
        if (s.stamp[w] == seen || value_[w] < lo || value_[w] > hi ||
            (!s.avoid.empty() && s.avoid[w]))
          continue;
        s.stamp[w] = seen;
        s.from[w] = static_cast<int64_t>(i);
        queue.push_back(w);
      }
    }
  }
  return true;
}

std::vector<Vec3> GeometricGraph::search(int64_t a, int64_t b, double lo, double hi,
                                         int64_t max_visits, Search &s) const {
  // Breadth-first from both ends at once, each step on the side with fewer nodes waiting, until
  // the two meet: in a region that surrounds the ends on all sides, each side then explores
  // about half the radius (on a surface, together about half the nodes of a one-sided search). A
  // node's stamp is the generation of the side that reached it (2g: from a, 2g + 1: from b),
  // `from` the edge it was reached by.
  if (s.stamp.size() != value_.size() || s.generation >= UINT32_MAX - 2) {
    s.stamp.assign(value_.size(), 0);
    s.from.assign(value_.size(), -1);
    s.generation = 0;
  }
  s.generation += 2;
  const uint32_t side_a = s.generation, side_b = s.generation + 1;
  std::vector<uint32_t> &stamp = s.stamp;
  std::vector<int64_t> &from = s.from;
  std::vector<int64_t> &qa = s.queue, &qb = s.queue_b;
  qa.assign(1, a);
  qb.assign(1, b);
  stamp[a] = side_a;
  from[a] = -1;
  int64_t meet_a = a == b ? a : -1, meet_b = a == b ? b : -1, meet_edge = -1;
  if (a != b) {
    stamp[b] = side_b;
    from[b] = -1;
  }
  std::size_t ha = 0, hb = 0; // the queues' heads
  int64_t visits = 0;
  while (meet_a < 0 && ha < qa.size() && hb < qb.size() && visits <= max_visits) {
    const bool on_a = qa.size() - ha <= qb.size() - hb;
    std::vector<int64_t> &queue = on_a ? qa : qb;
    const uint32_t own = on_a ? side_a : side_b, other = on_a ? side_b : side_a;
    const int64_t v = queue[on_a ? ha++ : hb++];
    ++visits;
    for (int64_t k = offset_[v]; k < offset_[v + 1]; ++k) {
      const int64_t w = adj_[k];
      if (stamp[w] == own || value_[w] < lo || value_[w] > hi ||
          (!s.avoid.empty() && s.avoid[w] && w != a && w != b))
        continue;
      if (stamp[w] == other) { // the two searches meet on this edge
        meet_a = on_a ? v : w;
        meet_b = on_a ? w : v;
        meet_edge = adj_edge_[k];
        break;
      }
      stamp[w] = own;
      from[w] = adj_edge_[k];
      queue.push_back(w);
    }
  }
  std::vector<Vec3> out;
  s.nodes.clear();
  if (meet_a < 0) {
    out = {position(a), position(b)};
    return out;
  }
  auto walk = [&](int64_t e, int64_t u) {
    const int64_t next = append_edge(e, u, out);
    s.nodes.push_back(next);
    return next;
  };
  // From meet_a back to a, reversed; then across the meeting edge and on to b.
  out.push_back(position(meet_a));
  s.nodes.push_back(meet_a);
  for (int64_t v = meet_a; v != a;)
    v = walk(from[v], v);
  std::reverse(out.begin(), out.end());
  std::reverse(s.nodes.begin(), s.nodes.end());
  if (meet_edge >= 0)
    walk(meet_edge, meet_a);
  for (int64_t v = meet_b; v != b;)
    v = walk(from[v], v);
  return out;
}

} // namespace hoct
