// Augmented join and split trees of a ScalarGraph by union-find sweeps (Carr, Snoeyink, Axen).
//
// Join tree: sweeping up, each node's parent is the node at which its sublevel-set component
// next grows or merges: parent(v) is above v; the root is the highest node. Leaves (no children)
// are the minima. Split tree: the mirror image (parent below, root the lowest node, leaves the
// maxima). Ties are broken by node id (ScalarGraph's total order).
#pragma once

#include "tree/scalar_graph.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

struct MergeTree {
  enum class Kind { Join, Split };
  Kind kind = Kind::Join;
  std::vector<int64_t> parent;   // -1 at the root (and for every root of a disconnected graph)
  std::vector<int32_t> children; // number of children
  int64_t roots = 0;             // connected components of the graph

  int64_t size() const { return static_cast<int64_t>(parent.size()); }
};

MergeTree join_tree(const ScalarGraph &graph);
MergeTree split_tree(const ScalarGraph &graph);

} // namespace hoct
