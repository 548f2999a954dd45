// The contour tree straight from node values and edge lists, for large graphs: the nodes are
// sorted once by the total order (value, then id) and everything after works on their ranks, so
// that both sweeps walk their arrays in order and the merge needs no index map (the same
// algorithm as join_tree / split_tree / merge_trees on a ScalarGraph, with the same result).
// The join and the split sweep may use different edges (the exact tree's connections differ).
#pragma once

#include "tree/contour_tree.hpp"
#include "tree/node_order.hpp"
#include "tree/scalar_graph.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// Augmented join tree in rank space: parent[r] is the rank of r's parent (above r), -1 at a
// root; children[r] counts the nodes whose parent is r. For the split tree, rank r stands for
// the node of rank n - 1 - r (the sweep runs downwards), and parent is in that numbering too.
struct RankMergeTree {
  std::vector<int64_t> parent;
  std::vector<int32_t> children;
};
// `rank[v]`: the rank of node v; edges with endpoints out of range are rejected.
RankMergeTree rank_join_tree(std::span<const int64_t> rank, std::span<const GraphEdge> edges);
RankMergeTree rank_split_tree(std::span<const int64_t> rank, std::span<const GraphEdge> edges);

struct SweepTimings {
  double order = 0, sweeps = 0, merge = 0; // seconds
};

// The contour tree (augmented or reduced) of the graph with the given node values, whose join
// tree comes from `join_edges` and split tree from `split_edges` (self-loops and duplicates are
// allowed). `threads` >= 2 runs the two sweeps at once.
ContourTree sweep_contour_tree(std::span<const double> values,
                               std::span<const GraphEdge> join_edges,
                               std::span<const GraphEdge> split_edges, bool augmented,
                               int threads = 1, SweepTimings *timings = nullptr);

} // namespace hoct
