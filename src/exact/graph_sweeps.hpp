// The join and split sweeps over the exact graph and their merge into the contour tree (in rank
// space, tree/sweep_contour_tree; the two sweeps on a thread each when there are two).
#pragma once

#include "exact/exact_graph.hpp"
#include "exact/exact_tree_options.hpp"
#include "tree/contour_tree.hpp"
#include "tree/sweep_contour_tree.hpp"

namespace hoct {

// The graph's edges as the sweeps take them (without arc geometry the edge chains are walked on
// the mesh's edges themselves).
SweepEdges exact_sweep_edges(const Mesh &mesh, const EdgeNodes &edge_nodes, const ExactGraph &graph,
                             const ExactTreeOptions &options);

ContourTree sweep_exact_graph(const Mesh &mesh, const EdgeNodes &edge_nodes,
                              const ExactGraph &graph, const ExactTreeOptions &options,
                              SweepTimings &timings, std::span<const uint8_t> keep = {});

} // namespace hoct
