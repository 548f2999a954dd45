// A surface cut open into disks along mesh edges, for the Reeb graph (docs/ALGORITHM.md §7).
//
// A component with holes, handles or a twist is not simply connected: its level sets can form
// loops that the join/split merge cannot see. Cut along a cut graph (interior edges whose
// complement is a disk), every component becomes a disk on which that merge is exact; gluing
// the disk's contour tree back along the cut's seams gives the Reeb graph. The cut graph is the
// complement of a spanning tree of the dual graph (cells across interior edges), pruned of its
// dangling edges (Erickson and Har-Peled): what is left joins the boundary loops and runs
// around the handles, typically a small fraction of the edges.
#pragma once

#include "mesh/mesh.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// The interior edges of the cut graph, ascending; empty when every component is a disk or a
// sphere. Needs a manifold topology (two cells per interior edge, one fan per vertex).
std::vector<int64_t> cut_graph_edges(const Topology &topology);

struct CutSurface {
  // The same cells, field and geometry; each vertex on the cut duplicated once per wedge of
  // cells between cut edges around it (its copies numbered consecutively, in the order of the
  // original vertices, so every edge keeps its orientation), each cut edge twice.
  Mesh mesh;
  // Per vertex of the cut mesh, the vertex of the original it is a copy of.
  std::vector<int64_t> vertex_origin;
  // Vertices of the cut mesh that are copies of one original vertex: group i is
  // copies[group_offset[i] .. group_offset[i + 1]) (vertices on the cut only, 2 or more each).
  std::vector<int64_t> group_offset{0}, copies;
  // Each cut edge as its two edges in the cut mesh (the same orientation as the original).
  std::vector<std::array<int64_t, 2>> seams;
};

// Cuts `mesh` open along `cut_edges` (from cut_graph_edges). Throws hoct::Error if the result is
// not one disk per component (a mesh the topology checks should have refused).
CutSurface cut_open(const Mesh &mesh, std::span<const int64_t> cut_edges, int threads = 1);

} // namespace hoct
