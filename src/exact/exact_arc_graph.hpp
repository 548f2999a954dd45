// The geometric graph of an exact tree, to draw its arcs on the surface (compute_arc_paths):
// the exact graph's nodes as points of cells, its edge-chain pieces placed by their cells, the
// cells' certified connections and degenerate cells' sub-edges with their paths' points.
#pragma once

#include <array>
#include <span>

#include "exact/exact_graph.hpp"
#include "exact/exact_tree_options.hpp"
#include "tree/geometric_graph.hpp"

#include <memory>

namespace hoct {

// Consumes the graph's geometry (curved pieces, GeoEdges).
std::shared_ptr<const GeometricGraph>
exact_arc_graph(const Mesh &mesh, const EdgeNodes &edge_nodes, ExactGraph &graph,
                const ExactTreeOptions &options, int threads,
                std::span<const std::array<int64_t, 2>> links = {});

} // namespace hoct
