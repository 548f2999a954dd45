// The graph the exact pipeline builds and sweeps: its nodes (vertices, edge critical points,
// interior critical points of regular cells, the nodes of degenerate cells' refinements), where
// each lies in the mesh, and its edges (cells' certified connections in the join or the split
// graph, edge chains and degenerate cells' sub-edges in both).
#pragma once

#include "cell/edge_nodes.hpp"
#include "exact/surface_graph_geometry.hpp"
#include "mesh/mesh.hpp"
#include "tree/scalar_graph.hpp"
#include "tree/tree_result.hpp"
#include "util/uninitialized_vector.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

// Where a node lies (trivial: see UninitializedVector).
struct NodeSource {
  int64_t cell;
  Vec2 uv;
  NodeLocation location;
  bool fallback; // in or on a degenerate cell's PL fallback
};

// A graph edge with the interior points of its path on the surface (arc geometry).
struct GeoEdge {
  int64_t a, b;
  std::vector<Vec3> inner;
};

struct ExactGraph {
  // Node ids: the mesh's vertices [0, edge_base), the edge nodes [edge_base, tail_base), then
  // the interior nodes of regular cells (in cell order) and the degenerate cells' nodes.
  int64_t edge_base = 0, tail_base = 0;
  UninitializedVector<double> values; // per node
  // Where the nodes from tail_base on lie (vertices and edge nodes are looked up in the mesh
  // and the edge nodes when asked: only tree nodes, and graph nodes with arc geometry, ask).
  std::vector<NodeSource> tail_source;
  // Vertices and edge nodes on degenerate cells: a flag per id below tail_base (sized at the
  // first mark).
  std::vector<uint8_t> fallback_marked;
  // The cells' lower connections (join graph only), upper ones (split graph only), and the
  // edges of both: degenerate cells' sub-edges and edge-chain pieces (those only where listed).
  UninitializedVector<GraphEdge> join_edges, split_edges, common_edges;
  // With arc geometry: the cells' connections and sub-edges with their paths' points.
  std::vector<GeoEdge> geo_edges;
  // The degenerate cells, ascending, and the reasons of each cell (FallbackReason bits).
  std::vector<int64_t> fallback_cells;
  UninitializedVector<uint8_t> fallback;

  // Edge chains. Without arc geometry the sweeps walk them on the mesh edges themselves
  // (EdgeChains), except the chains of these edges (with degenerate cells' lattice nodes),
  // listed in common_edges.
  std::vector<int64_t> listed_chains;
  // With arc geometry every chain piece is listed: common_edges[chain_first ..
  // chain_first + chain_pieces); those in curved cells also as segments of their cells.
  std::size_t chain_first = 0;
  int64_t chain_pieces = 0;
  UninitializedVector<int64_t> curved_piece_ids;
  UninitializedVector<EdgePiece> curved_pieces;

  int64_t size() const { return static_cast<int64_t>(values.size()); }
  void mark_fallback(int64_t id) {
    if (fallback_marked.empty())
      fallback_marked.assign(static_cast<std::size_t>(tail_base), 0);
    fallback_marked[static_cast<std::size_t>(id)] = 1;
  }
  // A new node of a degenerate cell's refinement.
  int64_t add_node(double value, int64_t cell, const Vec2 &uv, NodeLocation location) {
    values.push_back(value);
    tail_source.push_back({cell, uv, location, true});
    return size() - 1;
  }
  // Where node `id` lies.
  NodeSource source(const Topology &topo, const EdgeNodes &en, int64_t id) const;
};

} // namespace hoct
