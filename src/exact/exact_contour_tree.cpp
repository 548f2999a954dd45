#include "exact/exact_contour_tree.hpp"

#include "cell/edge_nodes.hpp"
#include "exact/cell_phase.hpp"
#include "exact/degenerate_cells.hpp"
#include "exact/edge_chains.hpp"
#include "exact/exact_arc_graph.hpp"
#include "exact/graph_assembly.hpp"
#include "exact/graph_sweeps.hpp"
#include "exact/seam_gluing.hpp"
#include "util/page_pool.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include "tree/stand_in_contraction.hpp"

#include <algorithm>

namespace hoct {
namespace {

// The tree's nodes where they lie in the mesh, its arcs and persistence pairs.
TreeResult tree_result(const Mesh &mesh, const EdgeNodes &en, const ExactGraph &g,
                       const ContourTree &ct, bool augmented) {
  return tree_result_of(ct, "exact", augmented, [&](TreeNode &n) {
    const NodeSource where = g.source(mesh.topology, en, n.graph_node);
    n.cell = where.cell;
    n.uv = where.uv;
    n.location = where.location;
    n.fallback = where.fallback;
    n.position = mesh.geometry.position(n.cell, n.uv[0], n.uv[1]);
  });
}

// The arcs of the fallback cells' PL stand-in no longer than twice its certified distance from
// the field there, contracted (tree/stand_in_contraction.hpp); returns how many. Augmented trees
// keep them (their regular nodes would be spliced out).
int64_t contract_stand_in(const DegenerateCells &degenerate, bool augmented, ContourTree &ct) {
  if (augmented || degenerate.max_error <= 0)
    return 0;
  const auto &errors = degenerate.node_error;
  std::vector<double> slack(static_cast<std::size_t>(ct.size()), -1.0);
  for (int64_t i = 0; i < ct.size(); ++i) {
    auto it = std::lower_bound(errors.begin(), errors.end(),
                               std::pair<int64_t, double>{ct.nodes[i], -1.0});
    if (it != errors.end() && it->first == ct.nodes[i])
      slack[i] = it->second;
  }
  StandInContraction c = contract_stand_in_arcs(ct, slack);
  if (c.contracted > 0)
    ct = std::move(c.tree);
  return c.contracted;
}

} // namespace

TreeResult exact_contour_tree(const Mesh &mesh, const ExactTreeOptions &opt) {
  // Large arrays freed by one phase give their pages to the next.
  const PageReuseScope reuse_pages;
  const Topology &topo = mesh.topology;
  const int64_t nc = topo.num_cells();
  const int threads = threads_for(nc, thread_count(opt.threads), opt.cells_per_thread);
  TreeTimings time;
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
  const EdgeNodes en = find_edge_nodes(topo, mesh.field, edge_options);
  done("edge critical points", time.edge_nodes);

  // 2. The cell phase: interior critical points, degeneracy, certified connections.
  CellPhase cells = run_cell_phase(mesh, en, opt, threads);
  done("cells: interior critical points and certified connections", time.cells);

  // 3. Graph assembly, 4. degenerate cells, 5. edge chains.
  const int refinement = opt.fallback_refinement > 0
                             ? opt.fallback_refinement
                             : std::max(4, 2 * std::max(1, mesh.field.max_degree()));
  CellTotals totals;
  ExactGraph graph = assemble_graph(mesh, en, std::move(cells), refinement, opt, threads, totals);
  const DegenerateCells degenerate =
      refine_degenerate_cells(mesh, en, refinement, opt.arc_geometry, graph);
  add_edge_chains(mesh, en, degenerate, opt, threads, graph);
  done("graph assembly: fallback cells and edge chains", time.graph_assembly);

  // 6. The join and split sweeps, 7. their merge.
  SweepTimings sweep_time;
  const std::vector<uint8_t> keep =
      opt.cut ? seam_nodes(*opt.cut, en, graph.size()) : std::vector<uint8_t>{};
  ContourTree ct = sweep_exact_graph(mesh, en, graph, opt, sweep_time, keep);
  // 8. On a surface cut open, the disks' tree glued back along the seams: the Reeb graph.
  GluedGraph glued;
  PathGluing gluing;
  if (opt.cut) {
    Stopwatch glue_clock;
    gluing = seam_gluing(*opt.cut, en, graph.values);
    glued = glue_paths(ct, gluing, !opt.augmented);
    ct = std::move(glued.graph);
    time.gluing = glue_clock.seconds();
  }
  const int64_t contracted = contract_stand_in(degenerate, opt.augmented, ct);
  time.sweeps = sweep_time.order + sweep_time.sweeps;
  time.merge = sweep_time.merge;
  if (opt.progress) {
    opt.progress("join and split sweeps", *time.sweeps);
    opt.progress("merge", *time.merge);
  }
  clock.lap();

  // 9. The result: the tree's nodes in the mesh, and the graph to draw its arcs.
  TreeResult r = tree_result(mesh, en, graph, ct, opt.augmented);
  offset_values(r, mesh.field.reference());
  if (opt.arc_geometry)
    r.graph = exact_arc_graph(mesh, en, graph, opt, threads, seam_links(gluing));
  time.output = clock.lap();

  ExactCounts &n = r.stats.exact.emplace();
  n.cells = nc;
  n.graph_nodes = graph.size();
  n.edge_critical_points = static_cast<int64_t>(en.nodes.size());
  n.interior_critical_points = totals.interior_nodes;
  n.connections_direct = totals.counters.direct;
  n.connections_traced = totals.counters.traced;
  n.connections_failed = totals.counters.failed;
  n.descent_steps = totals.counters.steps;
  n.fallback_cells = static_cast<int64_t>(graph.fallback_cells.size());
  n.fallback_by_reason = degenerate.reasons;
  n.fallback_error = degenerate.max_error;
  n.fallback_arcs_contracted = contracted;
  n.unresolved_interior_zeros = totals.unresolved_zeros;
  if (opt.cut) { // (compute_tree labels the result a Reeb graph, cut or not)
    r.loops = graph_loops(ct);
    r.stats.seam_edges = static_cast<int64_t>(opt.cut->seams.size());
    r.stats.seam_paths_nonmonotone = glued.nonmonotone_paths;
  }
  // The cell phase's two passes: their shares of its wall time are their shares of the threads'
  // time in them (on one thread, their own times).
  const double passes = totals.critical_seconds + totals.connection_seconds;
  const double critical_share = passes > 0 ? totals.critical_seconds / passes : 0.5;
  time.interior_critical_points = *time.cells * critical_share;
  time.connections = *time.cells * (1 - critical_share);
  r.stats.time = time;
  return r;
}

} // namespace hoct
