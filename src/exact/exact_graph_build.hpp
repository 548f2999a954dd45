// Steps 1-5 of the exact pipeline (exact_contour_tree): the edge nodes, the cell phase, the
// graph's assembly, the degenerate cells' refinements and the edge chains: the graph the sweeps
// walk, with what the statistics count. A whole mesh's tree sweeps it at once; a piece of a
// partitioned mesh reduces it to what its neighbours need (exact/piece_trees).
#pragma once

#include "cell/edge_nodes.hpp"
#include "exact/degenerate_cells.hpp"
#include "exact/exact_graph.hpp"
#include "exact/exact_tree_options.hpp"
#include "exact/graph_assembly.hpp"
#include "mesh/mesh.hpp"
#include "tree/tree_stats.hpp"

namespace hoct {

struct ExactGraphBuild {
  EdgeNodes edge_nodes;
  ExactGraph graph;
  DegenerateCells degenerate;
  CellTotals totals;
  int threads = 1; // for the cells (threads_for the mesh's size)
};

// Fills time.edge_nodes, cells and graph_assembly (and reports them to options.progress).
ExactGraphBuild build_exact_graph(const Mesh &mesh, const ExactTreeOptions &options,
                                  TreeTimings &time);

// The counts of the build (all but fallback_arcs_contracted).
ExactCounts exact_counts(const Mesh &mesh, const ExactGraphBuild &build);

// The cell phase's two passes' shares of its wall time (time.cells): their shares of the
// threads' time in them (on one thread, their own times).
void split_cell_time(const CellTotals &totals, TreeTimings &time);

} // namespace hoct
