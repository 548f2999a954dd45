#include "exact/exact_arc_graph.hpp"

#include "exact/graph_assembly.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>

namespace hoct {

std::shared_ptr<const GeometricGraph>
exact_arc_graph(const Mesh &mesh, const EdgeNodes &en, ExactGraph &g, const ExactTreeOptions &opt,
                int threads, std::span<const std::array<int64_t, 2>> links) {
  // Where each graph node lies (a point of a cell; mapped to the surface when drawn).
  const int64_t graph_nodes = static_cast<int64_t>(g.values.size());
  UninitializedVector<CellPoint> node_points(g.values.size());
  parallel_for(graph_nodes, gather_threads(graph_nodes, threads, opt),
               [&](int64_t begin, int64_t end, int) {
                 for (int64_t v = begin; v < end; ++v) {
                   const NodeSource where = g.source(mesh.topology, en, v);
                   node_points[v] = {where.cell, where.uv[0], where.uv[1]};
                 }
               });
  const std::size_t piece_count = static_cast<std::size_t>(g.chain_pieces);
  auto graph = std::make_shared<GeometricGraph>(
      std::vector<double>(g.values.begin(), g.values.end()),
      std::make_shared<const SurfaceGraphGeometry>(mesh.geometry, std::move(node_points),
                                                   g.chain_pieces, std::move(g.curved_piece_ids),
                                                   std::move(g.curved_pieces)));
  // The edge chains' pieces (placed by the graph's geometry), then the cells' connections and
  // the fallback cells' sub-edges with their interior points.
  // Last, `links` as edges without interior points (a cut surface's copies of one point).
  const std::size_t edges = piece_count + g.geo_edges.size() + links.size();
  std::vector<std::array<int64_t, 2>> ends(edges);
  std::vector<int64_t> point_offset(g.geo_edges.size() + links.size() + 1, 0);
  parallel_for(
      g.chain_pieces, gather_threads(g.chain_pieces, threads, opt),
      [&](int64_t begin, int64_t end, int) {
        for (int64_t i = begin; i < end; ++i)
          ends[i] = {g.common_edges[g.chain_first + i].a, g.common_edges[g.chain_first + i].b};
      });
  std::size_t points = 0;
  for (std::size_t j = 0; j < g.geo_edges.size(); ++j) {
    ends[piece_count + j] = {g.geo_edges[j].a, g.geo_edges[j].b};
    point_offset[j] = static_cast<int64_t>(points);
    points += g.geo_edges[j].inner.size();
  }
  for (std::size_t j = 0; j < links.size(); ++j) {
    ends[piece_count + g.geo_edges.size() + j] = links[j];
    point_offset[g.geo_edges.size() + j] = static_cast<int64_t>(points);
  }
  point_offset[g.geo_edges.size() + links.size()] = static_cast<int64_t>(points);
  UninitializedVector<Vec3> inner(points);
  std::size_t at = 0;
  for (const auto &e : g.geo_edges) {
    std::copy(e.inner.begin(), e.inner.end(), inner.begin() + static_cast<std::ptrdiff_t>(at));
    at += e.inner.size();
  }
  graph->set_edges(std::move(ends), std::move(point_offset), std::move(inner));
  graph->finish();
  return graph;
}

} // namespace hoct
