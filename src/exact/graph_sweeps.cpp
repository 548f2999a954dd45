#include "exact/graph_sweeps.hpp"

#include "util/parallel_for.hpp"

namespace hoct {

SweepEdges exact_sweep_edges(const Mesh &mesh, const EdgeNodes &en, const ExactGraph &g,
                             const ExactTreeOptions &opt) {
  SweepEdges edges{g.common_edges, g.join_edges, g.split_edges};
  // Without arc geometry the sweeps walk the edge chains on the mesh's edges themselves.
  if (!opt.arc_geometry)
    edges.chains = {mesh.topology.all_edge_vertices(),
                    std::span<const int64_t>(en.offset.data(), en.offset.size()), g.edge_base,
                    g.listed_chains};
  return edges;
}

ContourTree sweep_exact_graph(const Mesh &mesh, const EdgeNodes &en, const ExactGraph &g,
                              const ExactTreeOptions &opt, SweepTimings &timings,
                              std::span<const uint8_t> keep) {
  const int threads = threads_for(g.size(), thread_count(opt.threads), 8 * opt.cells_per_thread);
  return sweep_contour_tree(g.values, exact_sweep_edges(mesh, en, g, opt), opt.augmented, threads,
                            &timings, keep);
}

} // namespace hoct
