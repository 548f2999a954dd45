#include "tree/geometric_graph.hpp"

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
                                       int64_t max_visits) const {
  const double lo = std::min(value_[a], value_[b]), hi = std::max(value_[a], value_[b]);
  std::vector<Vec3> p = search(a, b, lo, hi, max_visits, scratch);
  // No path within the arc's values (the graph is sparser than the surface): below the upper
  // end's value, where the join tree connects the two ends of an arc (common on a field with
  // many features; a search for any path would visit far more nodes); then any path on the
  // surface rather than a chord through it.
  if (p.size() == 2 && a != b)
    p = search(a, b, -INFINITY, hi, max_visits, scratch);
  if (p.size() == 2 && a != b)
    p = search(a, b, -INFINITY, INFINITY, max_visits, scratch);
  return p;
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
  // Edge e's polyline from its end u to its other end (u excluded), appended to out; returns
  // that other end.
  auto walk = [&](int64_t e, int64_t u) {
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
