// Minimax spanning forests of a graph: built like the join tree (nodes taken in ascending total
// order, value then id, each joined by one edge to every lower component it touches) or like the
// split tree (descending). In the first, the path between two nodes has the smallest largest
// value of any path between them in the graph, so it stays below the upper of two nodes the join
// tree connects (the two ends of a contour tree's or Reeb graph's arc); in the second, above the
// lower of two nodes the split tree connects. Found by climbing to the common ancestor, in time
// proportional to its length: drawing an arc whose ends no search within its values connects
// (on a field with many features, whose sublevel sets wind through much of the surface) without
// searching half the surface for it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

class SublevelForest {
public:
  enum class Side { Sublevel, Superlevel };

  SublevelForest() = default;
  // The graph in CSR form: node v's neighbours adj[offset[v] .. offset[v + 1]), reached by the
  // edges adj_edge[...] (edge ids returned by path()); `order` its nodes in ascending total order.
  SublevelForest(Side side, std::span<const int64_t> order, std::span<const int64_t> offset,
                 std::span<const int64_t> adj, std::span<const int64_t> adj_edge);

  // The forest path from a to b: its nodes (a first, b last) and the edges between them
  // (edges[i] joins nodes[i] and nodes[i + 1]). False, and nothing written, when a and b lie in
  // different components.
  bool path(int64_t a, int64_t b, std::vector<int64_t> &nodes, std::vector<int64_t> &edges) const;

private:
  // Each node's parent in its rooted tree (-1 at a root: each component's last node), the
  // edge to it, and the node's depth.
  std::vector<int64_t> parent_, parent_edge_;
  std::vector<int32_t> depth_;
};

} // namespace hoct
