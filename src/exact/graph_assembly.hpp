// Graph assembly: the cells' results in global node ids. Vertices first, then edge nodes, then
// the interior critical points of regular cells (in cell order); the cells' lower connections
// go to the join graph, their upper ones to the split graph, each chunk into its own slots.
#pragma once

#include "cell/certified_path.hpp"
#include "exact/cell_phase.hpp"
#include "exact/exact_graph.hpp"

#include <cstdint>

namespace hoct {

// What the cells counted, summed over the chunks.
struct CellTotals {
  PathCounters counters;
  int64_t interior_nodes = 0, unresolved_zeros = 0;
  int64_t degenerate_points = 0, critical_corners = 0, critical_curves = 0;
  double degenerate_slack = 0;
  int64_t level_edges = 0;
  double critical_seconds = 0, connection_seconds = 0; // thread time in the two passes
};

// Consumes the cell phase. The arrays get room for the degenerate cells' refinements (K x K
// sub-triangles each), so that adding them does not reallocate arrays of millions of nodes.
ExactGraph assemble_graph(const Mesh &mesh, const EdgeNodes &edge_nodes, CellPhase &&phase,
                          int refinement, const ExactTreeOptions &options, int threads,
                          CellTotals &totals);

// Threads for the gathering loops: only where each gets enough items to pay for its start
// (128 x cells_per_thread items each).
int gather_threads(int64_t items, int threads, const ExactTreeOptions &options);

} // namespace hoct
