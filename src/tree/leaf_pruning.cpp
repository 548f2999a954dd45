#include "tree/leaf_pruning.hpp"

#include "tree/simplification.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

namespace hoct {

namespace {

constexpr int64_t kLeft = -1, kPruned = -2; // an arc's fate, when no splice merged it

} // namespace

LeafPruning::LeafPruning(std::span<const double> values,
                         std::span<const std::array<int64_t, 2>> arcs)
    : input_arcs_(arcs), nodes_(values.size()), fate_(arcs.size(), kLeft),
      spliced_into_(values.size(), -1), alive_(static_cast<int64_t>(values.size())) {
  const int64_t n = static_cast<int64_t>(values.size());
  // Bounds, so that nothing is moved as they grow: each node is pruned or spliced at most once.
  order_.reserve(values.size());
  made_.reserve(values.size());
  fate_.reserve(arcs.size() + values.size());
  for (int64_t v = 0; v < n; ++v)
    nodes_[v].value = values[v];
  for (std::size_t id = 0; id < arcs.size(); ++id) {
    const auto [a, b] = arcs[id];
    if (a < 0 || a >= b || b >= n)
      throw std::invalid_argument("leaf pruning: arc " + std::to_string(id) +
                                  " is not (lower node, upper node)");
    link(static_cast<int64_t>(id), a, b, 1);
  }
  sorted_.reserve(static_cast<std::size_t>(std::count_if(
      nodes_.begin(), nodes_.end(), [](const Node &x) { return x.up + x.down == 1; })));
  for (int64_t v = 0; v < n; ++v)
    add_candidate(v, true);
  std::sort(sorted_.begin(), sorted_.end());
}

void LeafPruning::link(int64_t id, int64_t lo, int64_t hi, int count) {
  Node &a = nodes_[lo], &b = nodes_[hi];
  a.up += count;
  a.up_end ^= hi;
  a.up_arc ^= id;
  b.down += count;
  b.down_end ^= lo;
  b.down_arc ^= id;
}

void LeafPruning::add_candidate(int64_t leaf, bool initial) {
  const Node &x = nodes_[leaf];
  if (x.up < 0 || x.up + x.down != 1)
    return;
  const int64_t s = x.up == 1 ? x.up_end : x.down_end;
  const Candidate c{std::abs(x.value - nodes_[s].value), leaf, s};
  if (initial) {
    sorted_.push_back(c);
  } else {
    heap_.push_back(c);
    std::push_heap(heap_.begin(), heap_.end(),
                   [](const Candidate &p, const Candidate &q) { return q < p; });
  }
}

bool LeafPruning::next_candidate(double limit, Candidate &c) {
  const bool sorted = next_sorted_ < sorted_.size(), heap = !heap_.empty();
  if (!sorted && !heap)
    return false;
  const bool from_heap = heap && (!sorted || heap_.front() < sorted_[next_sorted_]);
  c = from_heap ? heap_.front() : sorted_[next_sorted_];
  if (!(c.persistence < limit))
    return false;
  if (from_heap) {
    std::pop_heap(heap_.begin(), heap_.end(),
                  [](const Candidate &p, const Candidate &q) { return q < p; });
    heap_.pop_back();
  } else {
    ++next_sorted_;
  }
  return true;
}

void LeafPruning::prune(double limit) {
  Candidate c;
  while (alive_ > 2 && next_candidate(limit, c)) {
    const int64_t leaf = c.leaf, s = c.saddle;
    Node &x = nodes_[leaf];
    if (x.up < 0 || x.up + x.down != 1)
      continue;
    const bool is_min = x.up == 1; // its one arc goes up, to the saddle
    if ((is_min ? x.up_end : x.down_end) != s)
      continue; // a stale candidate: the leaf's saddle was spliced out since
    Node &y = nodes_[s];
    // Keep a valid contour tree: the saddle must keep an arc on the leaf's side.
    if ((is_min ? y.down : y.up) < 2)
      continue;
    const int64_t arc = is_min ? x.up_arc : x.down_arc;
    order_.push_back({leaf, s, arc, c.persistence});
    fate_[arc] = kPruned;
    if (is_min)
      link(arc, leaf, s, -1);
    else
      link(arc, s, leaf, -1);
    x.up = -1;
    --alive_;
    // A saddle left regular (one arc up, one down) is spliced out.
    if (y.up == 1 && y.down == 1) {
      const int64_t a = y.down_end, b = y.up_end, below = y.down_arc, above = y.up_arc;
      link(below, a, s, -1);
      link(above, s, b, -1);
      const int64_t merged = static_cast<int64_t>(fate_.size());
      made_.push_back({a, b});
      fate_.push_back(kLeft);
      fate_[below] = fate_[above] = merged;
      link(merged, a, b, 1);
      y.up = -1;
      --alive_;
      spliced_into_[s] = merged;
      add_candidate(a, false);
      add_candidate(b, false);
    } else if (y.up + y.down == 1) {
      add_candidate(s, false);
    }
  }
}

std::array<int64_t, 2> LeafPruning::ends(int64_t id) const {
  const int64_t m = static_cast<int64_t>(input_arcs_.size());
  return id < m ? input_arcs_[id] : made_[id - m];
}

std::vector<std::array<int64_t, 3>> LeafPruning::arcs_left() const {
  std::vector<std::array<int64_t, 3>> left;
  for (int64_t id = 0; id < static_cast<int64_t>(fate_.size()); ++id)
    if (fate_[id] == kLeft) {
      const auto e = ends(id);
      left.push_back({id, e[0], e[1]});
    }
  return left;
}

std::vector<Branch> LeafPruning::branches() const {
  // The root: the last arc left in the order (lower end, upper end, id).
  int64_t lo = -1, hi = -1, root = -1;
  for (const auto &[id, a, b] : arcs_left())
    if (std::tie(a, b, id) > std::tie(lo, hi, root))
      lo = a, hi = b, root = id;
  std::vector<Branch> out;
  out.reserve(order_.size() + 1);
  out.push_back({hi, lo, hi >= 0 ? nodes_[hi].value - nodes_[lo].value : 0.0, -1, 0});
  // Each arc's branch: that of the arc it ends in (pruned with a leaf, or the root). A splice
  // makes a later arc than the two it merges, so one pass from the last arc down suffices.
  std::vector<int64_t> branch(fate_.size(), -1);
  if (root >= 0)
    branch[root] = 0;
  for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
    branch[it->arc] = static_cast<int64_t>(out.size());
    out.push_back({it->leaf, it->saddle, it->persistence, -1, 0});
  }
  for (int64_t id = static_cast<int64_t>(fate_.size()) - 1; id >= 0; --id)
    if (fate_[id] >= 0)
      branch[id] = branch[fate_[id]];
  // A branch's parent: the branch whose arc took in its saddle (the root if none did).
  for (std::size_t b = 1; b < out.size(); ++b) {
    const int64_t into = spliced_into_[out[b].saddle];
    const int64_t parent = into >= 0 ? branch[into] : -1;
    out[b].parent = parent >= 0 ? parent : 0;
    // Parents come before their children.
    out[b].depth = out[out[b].parent].depth + 1;
  }
  return out;
}

} // namespace hoct
