// Degenerate cells (constant, with a critical curve, an uncertified or boundary gradient zero,
// a degenerate edge or edge node, a sector no certified path connects) fall back to the PL rule
// on a K x K refinement through their edge nodes: all its sub-edges go in both graphs, so the
// tree is that of the PL interpolant there. Lattice points on an edge are shared by both cells
// of the edge. A constant cell is one flat region already bounded by its edges' chains, and
// adds no sub-vertices.
#pragma once

#include "exact/exact_graph.hpp"
#include "tree/tree_stats.hpp"

#include <array>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace hoct {

struct DegenerateCells {
  std::array<int64_t, kFallbackReasons> reasons{}; // cells with each reason
  // How far the PL stand-in may be from the field: for every node of a refined cell, the
  // largest certified bound (poly/interpolation_error.hpp) over the refined cells it lies in
  // (0 for a constant cell's), sorted by node id, except the certain extrema
  // (cell/strict_extrema.hpp); and the largest of all.
  std::vector<std::pair<int64_t, double>> node_error;
  // The same before the certain extrema are taken out (their certainty on a piece of a mesh
  // depends on the cells beyond it: exact/piece_trees).
  std::vector<std::pair<int64_t, double>> node_bound;
  double max_error = 0;
  // The lattice nodes the refinements put on mesh edges: (edge, parameter from its lower vertex,
  // node id), sorted.
  std::vector<std::tuple<int64_t, double, int64_t>> lattice_on_edge;
};

// Refines graph.fallback_cells into the graph (nodes, common edges, with arc geometry their
// GeoEdges too) and marks every node on them as a fallback node.
DegenerateCells refine_degenerate_cells(const Mesh &mesh, const EdgeNodes &edge_nodes,
                                        int refinement, bool arc_geometry, ExactGraph &graph);

} // namespace hoct
