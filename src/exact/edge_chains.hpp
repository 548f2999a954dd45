// Edge chains: consecutive nodes along every mesh edge (its vertices, its critical points, the
// lattice nodes of degenerate cells' refinements). Between two of them the edge is monotone, so
// each piece is an edge of both the join and the split graph.
#pragma once

#include "exact/degenerate_cells.hpp"
#include "exact/exact_graph.hpp"
#include "exact/exact_tree_options.hpp"

namespace hoct {

// Without arc geometry, only the chains of edges with lattice nodes are listed (the sweeps walk
// the others on the mesh: ExactGraph::listed_chains); with it, every piece, those of curved
// cells also as segments of their edges' first cells (placed on the surface only if drawn).
void add_edge_chains(const Mesh &mesh, const EdgeNodes &edge_nodes,
                     const DegenerateCells &degenerate, const ExactTreeOptions &options,
                     int threads, ExactGraph &graph);

} // namespace hoct
