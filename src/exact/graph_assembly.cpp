#include "exact/graph_assembly.hpp"

#include "poly/lattice.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>

namespace hoct {

int gather_threads(int64_t items, int threads, const ExactTreeOptions &options) {
  return threads_for(items, threads, 128 * options.cells_per_thread);
}

ExactGraph assemble_graph(const Mesh &mesh, const EdgeNodes &en, CellPhase &&phase, int refinement,
                          const ExactTreeOptions &opt, int threads, CellTotals &totals) {
  const Topology &topo = mesh.topology;
  const Field &field = mesh.field;
  const int64_t nv = topo.num_vertices();
  const int64_t edge_base = nv;
  std::vector<CellChunk> &chunk_out = phase.chunks;
  const int64_t chunks = static_cast<int64_t>(chunk_out.size());
  ExactGraph g;
  // Global ids: vertices, edge nodes, then the interior nodes of regular cells (in cell order),
  // then extra lattice nodes on edges of fallback cells, then fallback cells' sub-vertices.
  std::vector<int64_t> node_base(chunks), join_base(chunks), split_base(chunks);
  int64_t next = edge_base + static_cast<int64_t>(en.nodes.size());
  std::size_t cell_join = 0, cell_split = 0, fallback_count = 0;
  PathCounters &counters = totals.counters;
  for (int64_t k = 0; k < chunks; ++k) {
    const CellChunk &ch = chunk_out[k];
    node_base[k] = next;
    next += static_cast<int64_t>(ch.nodes.size());
    join_base[k] = static_cast<int64_t>(cell_join);
    cell_join += ch.join.size();
    split_base[k] = static_cast<int64_t>(cell_split);
    cell_split += ch.split.size();
    fallback_count += ch.fallback_cells.size();
    counters.direct += ch.counters.direct;
    counters.traced += ch.counters.traced;
    counters.failed += ch.counters.failed;
    counters.steps += ch.counters.steps;
    totals.unresolved_zeros += ch.unresolved;
    totals.degenerate_points += ch.degenerate_points;
    totals.critical_corners += ch.critical_corners;
    totals.critical_curves += ch.critical_curves;
    totals.level_edges += ch.level_edges;
    totals.degenerate_slack = std::max(totals.degenerate_slack, ch.degenerate_slack);
    totals.critical_seconds += ch.critical_seconds;
    totals.connection_seconds += ch.connection_seconds;
  }
  totals.interior_nodes = next - edge_base - static_cast<int64_t>(en.nodes.size());
  // Large arrays, filled in parallel without being zeroed first.
  // The graph's edges: the cells' lower connections in the join graph only, their upper ones in
  // the split graph only; the edge chains and the fallback cells' sub-edges in both (stored once;
  // the chains listed only with arc geometry).
  UninitializedVector<GraphEdge> &join_edges = g.join_edges, &split_edges = g.split_edges,
                                 &common_edges = g.common_edges;
  join_edges.resize(cell_join);
  split_edges.resize(cell_split);

  // Room for the fallback cells' lattice nodes too (at most lattice_size(K) new ones each), so
  // that adding them does not reallocate (and copy) arrays of millions of nodes.
  const int K = refinement;
  const std::size_t fallback_room = fallback_count * static_cast<std::size_t>(lattice_size(K));
  UninitializedVector<double> &values = g.values;
  values.reserve(static_cast<std::size_t>(next) + fallback_room);
  values.resize(static_cast<std::size_t>(next));
  // Each fallback cell's 3 K^2 sub-edges plus the pieces its lattice nodes add.
  common_edges.reserve(fallback_room / static_cast<std::size_t>(lattice_size(K)) *
                       static_cast<std::size_t>(3 * K * K + 3 * K));
  // Where each node lies: vertices and edge nodes are looked up from the mesh and the edge
  // nodes when asked for (only tree nodes, and graph nodes with arc geometry, ask; an array for
  // millions of graph nodes cost more to fill than its few lookups save), the interior and
  // fallback nodes after them are stored.
  const int64_t tail_base = edge_base + static_cast<int64_t>(en.nodes.size());
  g.edge_base = edge_base;
  g.tail_base = tail_base;
  std::vector<NodeSource> &tail_source = g.tail_source;
  tail_source.reserve(static_cast<std::size_t>(next - tail_base) + fallback_room);
  tail_source.resize(static_cast<std::size_t>(next - tail_base));
  // Values of vertices and edge nodes.
  auto gather = [&](int64_t items) { return gather_threads(items, threads, opt); };
  parallel_for(nv, gather(nv), [&](int64_t begin, int64_t end, int) {
    for (int64_t v = begin; v < end; ++v) {
      values[v] = field.vertex_value(v);
    }
  });
  const int64_t edge_node_count = static_cast<int64_t>(en.nodes.size());
  parallel_for(edge_node_count, gather(edge_node_count), [&](int64_t begin, int64_t end, int) {
    for (int64_t i = begin; i < end; ++i)
      values[edge_base + i] = en.nodes[i].value;
  });
  // Interior nodes and the cells' connections in global ids, each chunk into its own slots.
  const int64_t gathered = next - edge_base + static_cast<int64_t>(cell_join + cell_split);
  parallel_for(chunks, gather(gathered), [&](int64_t begin, int64_t end, int) {
    for (int64_t k = begin; k < end; ++k) {
      const CellChunk &ch = chunk_out[k];
      const int64_t base = node_base[k];
      for (std::size_t i = 0; i < ch.nodes.size(); ++i) {
        values[base + i] = ch.nodes[i].value;
        tail_source[base - tail_base + i] = {ch.nodes[i].cell, ch.nodes[i].uv,
                                             NodeLocation::Interior, false};
      }
      auto resolve = [&](const GraphEdge &e) {
        return GraphEdge{e.a >= 0 ? e.a : base + (-1 - e.a), e.b >= 0 ? e.b : base + (-1 - e.b)};
      };
      for (std::size_t i = 0; i < ch.join.size(); ++i)
        join_edges[join_base[k] + i] = resolve(ch.join[i]);
      for (std::size_t i = 0; i < ch.split.size(); ++i)
        split_edges[split_base[k] + i] = resolve(ch.split[i]);
    }
  });
  // Graph edges with their geometry (interior polyline points), when asked for.
  std::vector<GeoEdge> &geo_edges = g.geo_edges;
  for (int64_t k = 0; k < chunks; ++k)
    for (GeoEdge &e : chunk_out[k].geo) {
      const int64_t base = node_base[k];
      geo_edges.push_back({e.a >= 0 ? e.a : base + (-1 - e.a), e.b >= 0 ? e.b : base + (-1 - e.b),
                           std::move(e.inner)});
    }
  // The fallback cells, ascending (chunks are in cell order).
  std::vector<int64_t> &fallback_cells = g.fallback_cells;
  fallback_cells.reserve(fallback_count);
  for (const CellChunk &ch : chunk_out)
    fallback_cells.insert(fallback_cells.end(), ch.fallback_cells.begin(), ch.fallback_cells.end());
  chunk_out = {};
  g.fallback = std::move(phase.fallback);

  return g;
}

} // namespace hoct
