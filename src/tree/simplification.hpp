// Persistence simplification of a contour tree by leaf pruning, and the branch decomposition it
// defines. Leaves are pruned in order of persistence (|value(leaf) - value(saddle)|, ties by
// node id): a maximum only where its saddle keeps another upward arc, a minimum only where its
// saddle keeps another downward arc, so the result is again a contour tree; saddles left with one
// arc up and one down become regular and are spliced out. Pruning everything down to the single
// arc from the global minimum to the global maximum gives the branch hierarchy: each pruned leaf
// is a branch (extremum, saddle, persistence), whose parent is the branch that finally contains
// its saddle; the last arc is the root branch.
#pragma once

#include "tree/contour_tree.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

struct Branch {
  int64_t extremum; // index into the tree's nodes (the root branch: the global maximum)
  int64_t saddle;   // where it merges (the root branch: the global minimum)
  double persistence;
  int64_t parent; // index into the branch list, -1 for the root
  int depth;      // 0 for the root
};

struct Simplification {
  ContourTree tree;             // the simplified tree (node indices are its own)
  std::vector<int64_t> kept;    // for each node of the simplified tree, its index in the input
  std::vector<Branch> branches; // of the INPUT tree: the root, then in reverse pruning order
  int64_t pruned_leaves = 0;
  int64_t removed_loops = 0;
};

// Removes every leaf branch whose persistence is below `threshold` (absolute). A reduced tree is
// expected (regular nodes are spliced out as they appear). On a Reeb graph leaves are pruned
// and loops kept; with `loops`, the loops whose essential pair is below the threshold are
// removed first (tree/loop_removal.hpp), and the branches are those of the graph left.
Simplification simplify(const ContourTree &tree, double threshold, bool loops = false);

// The branches of `simplify(tree, 0)` (the same list) without the simplified tree: of the tree
// with these node values (ascending in the total order) and arcs (lower node first).
std::vector<Branch> branch_decomposition(std::span<const double> values,
                                         std::span<const std::array<int64_t, 2>> arcs);

// The children of every branch, by decreasing persistence.
std::vector<std::vector<int64_t>> branch_children(const std::vector<Branch> &branches);

} // namespace hoct
