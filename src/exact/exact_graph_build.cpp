#include "exact/exact_graph_build.hpp"

#include "exact/cell_phase.hpp"
#include "exact/edge_chains.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include <algorithm>

namespace hoct {

ExactGraphBuild build_exact_graph(const Mesh &mesh, const ExactTreeOptions &opt,
                                  TreeTimings &time) {
  const Topology &topo = mesh.topology;
  ExactGraphBuild b;
  b.threads = threads_for(topo.num_cells(), thread_count(opt.threads), opt.cells_per_thread);
  Stopwatch clock;
  auto done = [&](const char *phase, std::optional<double> &slot) {
    slot = clock.lap();
    if (opt.progress)
      opt.progress(phase, *slot);
  };

  // 1. Edge nodes: the critical points of every mesh edge, once per edge.
  EdgeNodeOptions edge_options;
  edge_options.threads =
      threads_for(topo.num_edges(), thread_count(opt.threads), 2 * opt.cells_per_thread);
  b.edge_nodes = find_edge_nodes(topo, mesh.field, edge_options);
  done("edge critical points", time.edge_nodes);

  // 2. The cell phase: interior critical points, degeneracy, certified connections.
  CellPhase cells = run_cell_phase(mesh, b.edge_nodes, opt, b.threads);
  done("cells: interior critical points and certified connections", time.cells);

  // 3. Graph assembly, 4. degenerate cells, 5. edge chains.
  const int refinement = opt.fallback_refinement > 0
                             ? opt.fallback_refinement
                             : std::max(4, 2 * std::max(1, mesh.field.max_degree()));
  b.graph =
      assemble_graph(mesh, b.edge_nodes, std::move(cells), refinement, opt, b.threads, b.totals);
  b.degenerate = refine_degenerate_cells(mesh, b.edge_nodes, refinement, opt.arc_geometry, b.graph);
  add_edge_chains(mesh, b.edge_nodes, b.degenerate, opt, b.threads, b.graph);
  done("graph assembly: fallback cells and edge chains", time.graph_assembly);
  return b;
}

ExactCounts exact_counts(const Mesh &mesh, const ExactGraphBuild &b) {
  ExactCounts n;
  n.cells = mesh.topology.num_cells();
  n.graph_nodes = b.graph.size();
  n.edge_critical_points = static_cast<int64_t>(b.edge_nodes.nodes.size());
  n.level_edges = b.totals.level_edges;
  n.interior_critical_points = b.totals.interior_nodes;
  n.connections_direct = b.totals.counters.direct;
  n.connections_traced = b.totals.counters.traced;
  n.connections_failed = b.totals.counters.failed;
  n.descent_steps = b.totals.counters.steps;
  n.fallback_cells = static_cast<int64_t>(b.graph.fallback_cells.size());
  n.fallback_by_reason = b.degenerate.reasons;
  n.fallback_error = b.degenerate.max_error;
  n.unresolved_interior_zeros = b.totals.unresolved_zeros;
  n.degenerate_points = b.totals.degenerate_points;
  n.critical_corners = b.totals.critical_corners;
  n.critical_curves = b.totals.critical_curves;
  n.degenerate_slack = b.totals.degenerate_slack;
  return n;
}

void split_cell_time(const CellTotals &totals, TreeTimings &time) {
  const double passes = totals.critical_seconds + totals.connection_seconds;
  const double critical_share = passes > 0 ? totals.critical_seconds / passes : 0.5;
  time.interior_critical_points = time.cells.value_or(0) * critical_share;
  time.connections = time.cells.value_or(0) * (1 - critical_share);
}

} // namespace hoct
