#include "tree/loop_removal.hpp"

#include "tree/loop_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace hoct {
namespace {

// A simple cycle through arc `pivot` inside the arcs `arcs` (every node of even degree): the
// pivot's nodes joined by a shortest path that avoids the pivot. Its arcs (empty if none).
std::vector<int64_t> simple_cycle(const ContourTree &g, const std::vector<int64_t> &arcs,
                                  int64_t pivot) {
  std::vector<std::pair<int64_t, int64_t>> half; // (node, arc) for each end of each arc
  for (int64_t a : arcs)
    if (a != pivot)
      for (int64_t v : g.arcs[a])
        half.push_back({v, a});
  std::sort(half.begin(), half.end());
  const int64_t from = g.arcs[pivot][1], to = g.arcs[pivot][0];
  std::vector<int64_t> via(static_cast<std::size_t>(g.size()), -2); // the arc a node was reached by
  std::deque<int64_t> queue{from};
  via[static_cast<std::size_t>(from)] = -1;
  while (!queue.empty() && via[static_cast<std::size_t>(to)] == -2) {
    const int64_t v = queue.front();
    queue.pop_front();
    for (auto it = std::lower_bound(half.begin(), half.end(), std::pair<int64_t, int64_t>{v, -1});
         it != half.end() && it->first == v; ++it) {
      const auto &ends = g.arcs[it->second];
      const int64_t w = ends[0] == v ? ends[1] : ends[0];
      if (via[static_cast<std::size_t>(w)] == -2) {
        via[static_cast<std::size_t>(w)] = it->second;
        queue.push_back(w);
      }
    }
  }
  std::vector<int64_t> cycle;
  if (via[static_cast<std::size_t>(to)] == -2)
    return cycle; // cannot happen: the pivot lies on a cycle of `arcs`
  cycle.push_back(pivot);
  for (int64_t v = to; v != from;) {
    const int64_t a = via[static_cast<std::size_t>(v)];
    cycle.push_back(a);
    v = g.arcs[a][0] == v ? g.arcs[a][1] : g.arcs[a][0];
  }
  return cycle;
}

} // namespace

LoopRemoval remove_loops(const ContourTree &input, double threshold) {
  LoopRemoval out;
  out.graph = input;
  out.kept.resize(static_cast<std::size_t>(input.size()));
  for (int64_t v = 0; v < input.size(); ++v)
    out.kept[static_cast<std::size_t>(v)] = v;
  for (;;) {
    ContourTree &g = out.graph;
    const std::vector<LoopCycle> cycles = loop_cycles(g);
    const LoopCycle *least = nullptr;
    for (const LoopCycle &c : cycles)
      if (c.pair.persistence() < threshold &&
          (!least || c.pair.persistence() < least->pair.persistence()))
        least = &c;
    if (!least)
      break;
    // The pivot: the arc at the pair's bottom, the last of the reduced cycle.
    const std::vector<int64_t> cycle = simple_cycle(g, least->arcs, least->arcs.back());
    if (cycle.empty())
      break;
    std::vector<uint8_t> cut(g.arcs.size(), 0);
    std::vector<int64_t> nodes; // the cycle's, ascending
    for (int64_t a : cycle) {
      cut[static_cast<std::size_t>(a)] = 1;
      nodes.push_back(g.arcs[a][0]);
      nodes.push_back(g.arcs[a][1]);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    std::vector<std::array<int64_t, 2>> arcs;
    for (std::size_t a = 0; a < g.arcs.size(); ++a)
      if (!cut[a])
        arcs.push_back(g.arcs[a]);
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
      arcs.push_back({nodes[i], nodes[i + 1]});
    // Nodes of the cycle left with one arc down and one up are regular: spliced out.
    std::vector<int32_t> up(static_cast<std::size_t>(g.size()), 0),
        down(static_cast<std::size_t>(g.size()), 0);
    for (const auto &a : arcs) {
      ++up[static_cast<std::size_t>(a[0])];
      ++down[static_cast<std::size_t>(a[1])];
    }
    std::vector<uint8_t> gone(static_cast<std::size_t>(g.size()), 0);
    for (int64_t v : nodes)
      gone[static_cast<std::size_t>(v)] =
          up[static_cast<std::size_t>(v)] == 1 && down[static_cast<std::size_t>(v)] == 1;
    // Splice: follow each arc's ends through spliced nodes (each has one arc on either side).
    std::vector<int64_t> above(static_cast<std::size_t>(g.size()), -1);
    for (const auto &a : arcs)
      if (gone[static_cast<std::size_t>(a[0])])
        above[static_cast<std::size_t>(a[0])] = a[1];
    std::vector<int64_t> index(static_cast<std::size_t>(g.size()), -1);
    ContourTree next;
    std::vector<int64_t> kept;
    for (int64_t v = 0; v < g.size(); ++v)
      if (!gone[static_cast<std::size_t>(v)]) {
        index[static_cast<std::size_t>(v)] = next.size();
        next.nodes.push_back(g.nodes[static_cast<std::size_t>(v)]);
        next.values.push_back(g.values[static_cast<std::size_t>(v)]);
        kept.push_back(out.kept[static_cast<std::size_t>(v)]);
      }
    for (const auto &a : arcs) {
      if (gone[static_cast<std::size_t>(a[0])])
        continue; // taken along from the arc below it
      int64_t hi = a[1];
      while (gone[static_cast<std::size_t>(hi)])
        hi = above[static_cast<std::size_t>(hi)];
      next.arcs.push_back(
          {index[static_cast<std::size_t>(a[0])], index[static_cast<std::size_t>(hi)]});
    }
    std::sort(next.arcs.begin(), next.arcs.end());
    out.graph = std::move(next);
    out.kept = std::move(kept);
    ++out.removed;
  }
  return out;
}

} // namespace hoct
