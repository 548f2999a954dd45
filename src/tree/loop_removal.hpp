// Removing the loops of a Reeb graph whose essential pair (tree/loop_pairs.hpp) is below a
// threshold, as simplification removes short leaf branches: the smallest such loop first, by
// collapsing a simple cycle of its class (all of it between the pair's bottom and top) into one
// monotone chain of the same nodes, then splicing out the nodes that became regular; the pairs
// are recomputed and the next smallest loop below the threshold goes, until none is. A collapsed
// cycle's nodes keep their values and their other arcs: the graph is that of a field changed by
// at most the loop's persistence, within the band of the pair (docs/ALGORITHM.md §7).
#pragma once

#include "tree/contour_tree.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

struct LoopRemoval {
  ContourTree graph;         // the loops at or above the threshold left, nodes ascending
  std::vector<int64_t> kept; // for each node of `graph`, its index in the input
  int64_t removed = 0;       // loops removed
};

LoopRemoval remove_loops(const ContourTree &graph, double threshold);

} // namespace hoct
