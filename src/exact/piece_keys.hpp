// Each graph node of a piece's exact graph named as the whole mesh names it (NodeKey), with
// the pieces that may hold it, and the kept nodes' places in the whole (PieceNode): what the
// pieces of a partitioned mesh exchange (exact/piece_trees, exact/reeb_pieces).
#pragma once

#include "exact/exact_graph_build.hpp"
#include "exact/piece_trees.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hoct {

// Whether a piece span lies within pieces first .. last.
inline bool within(const std::array<int32_t, 2> &span, int32_t first, int32_t last) {
  return span[0] >= first && span[1] <= last;
}

// Each graph node's key and span.
class PieceKeys {
public:
  // `uncut`, `vertex_origin`: for a mesh cut open (mesh/cut_surface), the piece's own topology
  // and the vertex there each vertex of `mesh` is a copy of (a copy is its point).
  PieceKeys(const Mesh &mesh, const PiecePlace &place, const ExactGraphBuild &b, int K,
            const Topology *uncut = nullptr, std::span<const int64_t> vertex_origin = {})
      : mesh_(mesh), place_(place), b_(b), uncut_(uncut ? *uncut : mesh.topology),
        origin_(vertex_origin) {
    const ExactGraph &g = b.graph;
    for (const auto &[e, t, id] : b.degenerate.lattice_on_edge)
      lattice_[id] = {e, std::llround(t * K)};
    // The index of each interior and sub-vertex node among its cell's (they are consecutive).
    tail_index_.resize(g.tail_source.size());
    int64_t last_cell = -1, next = 0;
    bool last_fallback = false;
    for (std::size_t i = 0; i < g.tail_source.size(); ++i) {
      if (lattice_.count(g.tail_base + static_cast<int64_t>(i)))
        continue;
      const NodeSource &s = g.tail_source[i];
      if (s.cell != last_cell || s.fallback != last_fallback)
        next = 0;
      tail_index_[i] = next++;
      last_cell = s.cell;
      last_fallback = s.fallback;
    }
  }

  NodeKey key(int64_t id) const {
    const ExactGraph &g = b_.graph;
    const Topology &topo = mesh_.topology;
    if (id < g.edge_base)
      return {NodeKey::Vertex, point(id), 0, 0};
    if (id < g.tail_base) {
      const int64_t i = id - g.edge_base;
      const auto &off = b_.edge_nodes.offset;
      const int64_t e = std::upper_bound(off.begin(), off.end(), i) - off.begin() - 1;
      const auto &ev = topo.edge_vertices(e);
      return {NodeKey::EdgeNode, point(ev[0]), point(ev[1]), i - off[e]};
    }
    // Fallback lattice nodes on edges by their edge and step (refine_degenerate_cells numbers
    // them in that order), the other fallback nodes by their cell and rank among its nodes.
    if (auto it = lattice_.find(id); it != lattice_.end()) {
      const auto &ev = topo.edge_vertices(it->second.first);
      return {NodeKey::EdgeLattice, point(ev[0]), point(ev[1]), it->second.second};
    }
    const std::size_t t = static_cast<std::size_t>(id - g.tail_base);
    const NodeSource &s = g.tail_source[t];
    return {s.fallback ? NodeKey::SubVertex : NodeKey::Interior, place_.first_triangle + s.cell, 0,
            tail_index_[t]};
  }

  // The pieces that may hold node `id`: its vertex's, its edge's (vertex and edge nodes, lattice
  // nodes on edges), or this piece alone.
  std::array<int32_t, 2> span(int64_t id) const {
    const ExactGraph &g = b_.graph;
    if (id < g.edge_base)
      return place_.point_span[piece_point(id)];
    if (id < g.tail_base) {
      const auto &off = b_.edge_nodes.offset;
      return edge_span(std::upper_bound(off.begin(), off.end(), id - g.edge_base) - off.begin() -
                       1);
    }
    if (auto it = lattice_.find(id); it != lattice_.end())
      return edge_span(it->second.first);
    return {place_.piece, place_.piece};
  }

  // The pieces of an edge's cells hold both its ends: within both ends' spans.
  std::array<int32_t, 2> edge_span(int64_t e) const {
    const Topology &topo = mesh_.topology;
    const auto &ev = topo.edge_vertices(e);
    const auto &sa = place_.point_span[piece_point(ev[0])],
               &sb = place_.point_span[piece_point(ev[1])];
    return {std::max(sa[0], sb[0]), std::min(sa[1], sb[1])};
  }

  // The whole's point at vertex v.
  int64_t point(int64_t v) const { return place_.global_point[piece_point(v)]; }

private:
  int64_t piece_point(int64_t v) const {
    return uncut_.vertex_point(origin_.empty() ? v : origin_[v]);
  }

  const Mesh &mesh_;
  const PiecePlace &place_;
  const ExactGraphBuild &b_;
  const Topology &uncut_;
  std::span<const int64_t> origin_;
  std::unordered_map<int64_t, std::pair<int64_t, int64_t>> lattice_; // id -> (edge, step)
  std::vector<int64_t> tail_index_;
};

// The fallback lattice's step count on edges: the options', or the exact pipeline's default.
int lattice_steps(const Mesh &mesh, const ExactTreeOptions &options);

// The graph's nodes ascending in the whole's total order (value, then key).
std::vector<int64_t> key_order(std::span<const double> values, const PieceKeys &keys, int threads);

// The kept nodes `ids` as PieceNodes: key, value, span, place in the whole; a node with
// shared[id] set (one other pieces may hold, or a copy of a point the piece's own cut split)
// gets the certified bound of the fallback stand-in as its slack and its strictness as an
// extremum, any other the stand-in's error at it.
std::vector<PieceNode> piece_nodes(const Mesh &mesh, const PiecePlace &place,
                                   const ExactGraphBuild &build, const PieceKeys &keys,
                                   std::span<const int64_t> ids, std::span<const uint8_t> shared);

} // namespace hoct
