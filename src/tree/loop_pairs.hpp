// The essential pairs of a Reeb graph's loops (extended persistence, Cohen-Steiner, Edelsbrunner
// and Harer 2009; docs/ALGORITHM.md §7): one pair per independent loop, from the saddle where
// the ascending sweep closes it (its top, a down-fork whose lower arcs already meet below) to the
// saddle of the highest bottom any cycle of it can be given (an up-fork). For every band of
// values [t, s], the pairs with top at most s and bottom at least t number the independent loops
// made of arcs inside the band: the pairing of the sublevel and the superlevel filtrations of
// the graph's cycle space, computed by reducing an ascending cycle basis over the arcs ordered
// by their lower ends, highest first (cycles live in the graph's 2-core: leaves are pruned).
#pragma once

#include "tree/contour_tree.hpp"
#include "tree/persistence.hpp"

#include <vector>

namespace hoct {

// Pairs of kind Loop: birth = the loop's top node, death = its bottom node (indices of `graph`,
// whose nodes ascend in the total order). None for a tree.
std::vector<PersistencePair> loop_pairs(const ContourTree &graph);

// Each loop's pair with the reduced cycle that carries it: arcs (indices of graph.arcs) whose
// every node has an even number of them, all between the pair's bottom and top (lower ends at
// or above the bottom, upper ends at or below the top), the bottom's arc among them.
struct LoopCycle {
  PersistencePair pair;
  std::vector<int64_t> arcs;
};
std::vector<LoopCycle> loop_cycles(const ContourTree &graph);

} // namespace hoct
