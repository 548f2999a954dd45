// The exact tree of a surface cut open into disks (mesh/cut_surface), glued back along its
// seams into the surface's Reeb graph (tree/path_gluing; docs/ALGORITHM.md §7).
#pragma once

#include "cell/edge_nodes.hpp"
#include "mesh/cut_surface.hpp"
#include "tree/path_gluing.hpp"
#include "tree/tree_stats.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

namespace hoct {

// One flag per graph node (`nodes` of them): the copies of vertices on the cut and the edge
// nodes of the seams, which the sweeps must keep in the reduced tree for the gluing to find.
std::vector<uint8_t> seam_nodes(const CutSurface &cut, const EdgeNodes &edge_nodes, int64_t nodes);

// What is one point and one curve: the copies of each vertex; each seam's two chains (its ends
// and edge nodes, both copies computed from one polynomial, so they have the same nodes at the
// same values), piece by piece; the fallback lattice's nodes at one place on both copies of a
// seam (`lattice_on_edge`: (edge, t, node), by edge; exact/degenerate_cells), as on the uncut
// edge. `values`: the graph's node values.
PathGluing seam_gluing(const CutSurface &cut, const EdgeNodes &edge_nodes,
                       std::span<const double> values,
                       std::span<const std::tuple<int64_t, double, int64_t>> lattice_on_edge = {});

// The pairs of nodes that are one point (each group's members in a chain, the seams' chains
// node by node): links that join the disks back into the surface for drawing arcs.
std::vector<std::array<int64_t, 2>> seam_links(const PathGluing &gluing);

// Counts of the cut mesh's graph as the uncut mesh's: each point's copies and each seam's edge
// nodes (both copies have them) once. They are then the same for any cut (one process's or the
// pieces' of a partitioned mesh).
void count_copies_once(const CutSurface &cut, const EdgeNodes &edge_nodes, ExactCounts &counts);

} // namespace hoct
