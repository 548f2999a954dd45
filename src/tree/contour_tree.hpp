// The contour tree, merged from the augmented join and split trees (Carr, Snoeyink, Axen 2003),
// and its reduction to critical nodes (degree != 2, or degree 2 with both arcs on one side).
#pragma once

#include "tree/merge_tree.hpp"
#include "tree/scalar_graph.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

enum class NodeType : uint8_t { Minimum, Maximum, Saddle, Regular };
const char *to_string(NodeType t);

struct ContourTree {
  // The nodes kept, as ids of the graph they came from, ascending in the total order.
  std::vector<int64_t> nodes;
  std::vector<double> values; // values[i] = value of nodes[i]
  // Arcs as pairs of indices into `nodes`, lower node first.
  std::vector<std::array<int64_t, 2>> arcs;

  int64_t size() const { return static_cast<int64_t>(nodes.size()); }
  // Up- and down-degree of each node (arcs to higher / lower nodes).
  std::vector<std::array<int32_t, 2>> degrees() const;
  // Minimum: no lower arc; maximum: no upper arc; regular: one of each; else saddle.
  std::vector<NodeType> types() const;
};

// The join/split merge on plain arrays over nodes 0..n-1 (Carr, Snoeyink, Axen): join-tree parent
// (above, -1 at a root) and number of children, split-tree parent (below) and number of
// children; leaves of either tree are peeled off one by one (children tracked by count and sum,
// so a node with one child knows it). Returns the arcs as node pairs (smaller number first).
std::vector<std::array<int64_t, 2>> merge_join_split(std::vector<int64_t> jparent,
                                                     std::vector<int32_t> jdown,
                                                     std::vector<int64_t> sparent,
                                                     std::vector<int32_t> sup);

// Merges augmented join and split trees of the same graph into the augmented contour tree (every
// graph node, n - 1 arcs per connected component). Requires both trees from one ScalarGraph.
ContourTree merge_trees(const ScalarGraph &graph, const MergeTree &join, const MergeTree &split);

// The first Betti number of a graph (arcs - nodes + connected components): 0 for a tree, the
// number of independent loops of a Reeb graph.
int64_t graph_loops(const ContourTree &graph);

// Sorts `arcs` (stably: parallel arcs keep their order) and returns where each went: the new
// index of arc i is the result's [i].
std::vector<int64_t> sort_arcs(std::vector<std::array<int64_t, 2>> &arcs);

// Removes regular nodes (exactly one lower and one upper arc), splicing their arcs.
ContourTree reduce(const ContourTree &augmented);

// Both steps: the join and split trees of `graph`, merged, optionally reduced.
ContourTree contour_tree(const ScalarGraph &graph, bool augmented = false);

} // namespace hoct
