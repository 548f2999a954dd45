#include "pl/pl_contour_tree.hpp"

#include "pl/pl_cut.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/page_pool.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"
#include "util/uninitialized_vector.hpp"

namespace hoct {

TreeResult pl_contour_tree(const PlMesh &m, bool augmented, const std::string &method,
                           bool with_graph, int threads, bool reeb) {
  const PageReuseScope reuse_pages; // the edge list's pages serve the sweeps after it
  Stopwatch clock;
  // Not a disk or a sphere: the disks the mesh is cut into, whose tree is glued back below.
  const PlCut cut = reeb ? cut_pl_mesh(m, threads) : PlCut{};
  const bool glue = cut.seam_edges > 0;
  const double cut_seconds = clock.lap();
  const auto &triangles = glue ? cut.triangles : m.triangles;
  const std::span<const double> values = glue ? cut.values : m.values;
  // The triangles' sides (an interior edge twice: the sweeps do not mind duplicates).
  UninitializedVector<GraphEdge> edges;
  edges.resize(triangles.size() * 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      edges[3 * t + k] = {triangles[t][k], triangles[t][(k + 1) % 3]};
  const double graph_seconds = clock.lap();
  SweepTimings sweep;
  // A thread per sweep only where it pays (starting one costs more on small meshes).
  const int sweep_threads =
      threads_for(static_cast<int64_t>(values.size()), thread_count(threads), 8192);
  ContourTree ct =
      sweep_contour_tree(values, {edges, {}, {}}, augmented, sweep_threads, &sweep, cut.keep);
  clock.lap();
  GluedGraph glued;
  if (glue) {
    glued = glue_paths(ct, cut.gluing, !augmented);
    ct = std::move(glued.graph);
    // Each node by its point of the PL mesh (a group's lowest copy: the order is kept).
    for (int64_t &v : ct.nodes)
      v = cut.point[v];
  }
  const double gluing_seconds = clock.lap();

  double pairs_seconds = 0;
  TreeResult r = tree_result_of(
      ct, method, augmented,
      [&](TreeNode &n) {
        const int64_t v = n.graph_node;
        n.position = m.points[v];
        if (v < static_cast<int64_t>(m.source_cell.size()) && m.source_cell[v] >= 0) {
          n.cell = m.source_cell[v];
          n.uv = m.source_uv[v];
          n.location = classify_location(n.uv[0], n.uv[1]);
        }
      },
      &pairs_seconds, sweep_threads);
  offset_values(r, m.reference);
  // The persistence pairs, and the rest of the result (its nodes, placed; the graph for the
  // arcs' paths) as output.
  r.stats.time.pairs = pairs_seconds;
  double output_seconds = clock.lap() - pairs_seconds;
  if (with_graph) {
    const ScalarGraph g = m.graph();
    auto graph = std::make_shared<GeometricGraph>(m.points, m.values);
    for (int64_t v = 0; v < g.size(); ++v)
      for (int64_t u : g.neighbors(v))
        if (u > v)
          graph->add_edge(v, u);
    graph->finish();
    r.graph = std::move(graph);
    output_seconds += clock.lap();
  }
  r.stats.time.output = output_seconds;
  r.stats.pl =
      PlCounts{static_cast<int64_t>(m.values.size()), static_cast<int64_t>(m.triangles.size())};
  r.reeb_graph = reeb;
  if (glue) {
    r.loops = graph_loops(ct);
    r.stats.seam_edges = cut.seam_edges;
    r.stats.seam_paths_nonmonotone = glued.nonmonotone_paths;
    r.stats.time.gluing = gluing_seconds;
  }
  if (reeb)
    r.stats.time.cut = cut_seconds;
  r.stats.time.graph = graph_seconds;
  r.stats.time.sweeps = sweep.order + sweep.sweeps;
  r.stats.time.merge = sweep.merge;
  return r;
}

} // namespace hoct
