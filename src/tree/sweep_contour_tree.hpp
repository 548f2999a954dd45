// The contour tree straight from node values and edge lists, for large graphs: the nodes are
// sorted once by the total order (value, then id) and everything after works on their ranks, so
// that both sweeps walk their arrays in order and the merge needs no index map (the same
// algorithm as join_tree / split_tree / merge_trees on a ScalarGraph, with the same result).
// The join and the split sweep may use different edges (the exact tree's connections differ).
#pragma once

#include "tree/contour_tree.hpp"
#include "tree/node_order.hpp"
#include "tree/scalar_graph.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// Chains of nodes along lines (the exact tree's mesh edges with their edge nodes), whose
// consecutive nodes are edges of both sweeps, without a list of those edges in memory: chain i
// runs from ends[i][0] through nodes first + offset[i] .. first + offset[i + 1] - 1 to
// ends[i][1]. Chains listed in `skip` (ascending) are left out; their caller lists their pieces
// itself.
struct EdgeChains {
  std::span<const std::array<int64_t, 2>> ends;
  std::span<const int64_t> offset; // ends.size() + 1 entries, ascending (or none without ends)
  int64_t first = 0;
  std::span<const int64_t> skip;
};

// The graph's edges: `common` ones and the chains' pieces in both sweeps, `join_only` in the
// join sweep, `split_only` in the split sweep (self-loops and duplicates are allowed).
struct SweepEdges {
  std::span<const GraphEdge> common, join_only, split_only;
  EdgeChains chains = {};
};

struct SweepTimings {
  double order = 0, sweeps = 0, merge = 0; // seconds
};

// The contour tree (augmented or reduced) of the graph with the given node values, whose join
// tree comes from common + join_only edges and split tree from common + split_only edges.
// `threads` >= 2 runs the two sweeps at once. The reduced tree also keeps the regular nodes `v`
// with keep[v] != 0 (`keep` empty, or one flag per node).
ContourTree sweep_contour_tree(std::span<const double> values, const SweepEdges &edges,
                               bool augmented, int threads = 1, SweepTimings *timings = nullptr,
                               std::span<const uint8_t> keep = {});
// The join and the split tree of the same graph restricted to a set of nodes: the graph's own
// critical nodes (minima, maxima, join and split saddles: not exactly one child in each tree)
// and those with keep[v] != 0. Two such restrictions of graphs sharing the kept nodes they
// have in common, put together as one graph's join and split edges, have the join and split
// trees of the union of the graphs restricted to those nodes (sublevel and superlevel
// connectivity between kept nodes is preserved): the pieces of a partitioned mesh are merged
// this way (exact/piece_trees). `order`, if given, is the nodes in ascending total order
// (otherwise value, then id).
struct KeptMergeTrees {
  std::vector<int64_t> nodes;        // the kept nodes, in ascending order
  std::vector<int64_t> join_parent;  // per kept node, the index of its join-tree parent, or -1
  std::vector<int64_t> split_parent; // the same in the split tree (parents lie below)
};
KeptMergeTrees sweep_merge_trees(std::span<const double> values, const SweepEdges &edges,
                                 std::span<const uint8_t> keep, int threads = 1,
                                 std::span<const int64_t> order = {});

// The same with 64-bit rank indices whatever the size (sweep_contour_tree uses them only for
// more than 2^31 nodes or edges): lets the tests run that path on small graphs.
ContourTree sweep_contour_tree_wide(std::span<const double> values, const SweepEdges &edges,
                                    bool augmented, int threads = 1);

} // namespace hoct
