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

void GeometricGraph::finish() {
  const int64_t n = size();
  offset_.assign(n + 1, 0);
  for (const auto &e : ends_) {
    ++offset_[e[0] + 1];
    ++offset_[e[1] + 1];
  }
  std::partial_sum(offset_.begin(), offset_.end(), offset_.begin());
  adj_.resize(offset_[n]);
  adj_edge_.resize(offset_[n]);
  std::vector<int64_t> fill(offset_.begin(), offset_.end() - 1);
  for (std::size_t i = 0; i < ends_.size(); ++i) {
    const auto &e = ends_[i];
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
  // end's value, where the join tree connects the two ends of an arc (on a field with many
  // features, a third of the arcs; searching any path instead visited 4x the nodes); then any
  // path on the surface rather than a chord through it.
  if (p.size() == 2 && a != b)
    p = search(a, b, -INFINITY, hi, max_visits, scratch);
  if (p.size() == 2 && a != b)
    p = search(a, b, -INFINITY, INFINITY, max_visits, scratch);
  return p;
}

std::vector<Vec3> GeometricGraph::search(int64_t a, int64_t b, double lo, double hi,
                                         int64_t max_visits, Search &s) const {
  // Breadth-first search; a node's mark is its generation, `from` the edge it was reached by.
  if (s.stamp.size() != position_.size() || s.generation == UINT32_MAX) {
    s.stamp.assign(position_.size(), 0);
    s.from.assign(position_.size(), -1);
    s.generation = 0;
  }
  const uint32_t gen = ++s.generation;
  std::vector<int64_t> &queue = s.queue;
  queue.assign(1, a);
  std::vector<uint32_t> &stamp = s.stamp;
  std::vector<int64_t> &from = s.from;
  stamp[a] = gen;
  from[a] = -1;
  bool found = a == b;
  for (std::size_t q = 0; q < queue.size() && !found; ++q) {
    if (static_cast<int64_t>(q) > max_visits)
      break;
    const int64_t v = queue[q];
    for (int64_t k = offset_[v]; k < offset_[v + 1]; ++k) {
      const int64_t w = adj_[k];
      if (stamp[w] == gen || value_[w] < lo || value_[w] > hi)
        continue;
      stamp[w] = gen;
      from[w] = adj_edge_[k];
      if (w == b) {
        found = true;
        break;
      }
      queue.push_back(w);
    }
  }
  std::vector<Vec3> out;
  if (!found) {
    out = {position_[a], position_[b]};
    return out;
  }
  // Walk back from b, then reverse.
  int64_t v = b;
  out.push_back(position_[b]);
  while (v != a) {
    const int64_t e = from[v];
    const auto &ends = ends_[e];
    const bool forward = ends[1] == v; // the edge runs ends[0] -> ends[1] = v
    const int64_t u = forward ? ends[0] : ends[1];
    // Interior points from v back to u.
    if (forward)
      for (int64_t i = point_offset_[e + 1] - 1; i >= point_offset_[e]; --i)
        out.push_back(points_[i]);
    else
      for (int64_t i = point_offset_[e]; i < point_offset_[e + 1]; ++i)
        out.push_back(points_[i]);
    out.push_back(position_[u]);
    v = u;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

} // namespace hoct
