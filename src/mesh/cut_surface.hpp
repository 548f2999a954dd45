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
#include <utility>
#include <vector>

namespace hoct {

// The interior edges of the cut graph, ascending; empty when every component is a disk or a
// sphere. Needs a manifold topology (two cells per interior edge, one fan per vertex).
std::vector<int64_t> cut_graph_edges(const Topology &topology);

// The corners of a triangle mesh cut open along `cut_edges`: each vertex on the cut copied once
// per wedge of cells between cut (or boundary) edges around it, its copies numbered
// consecutively in the order of the original vertices (so no edge changes orientation). Only the
// vertices on the cut are walked: every other corner keeps its vertex, renumbered.
struct CornerCut {
  // Per vertex v of the original, its copies in the cut mesh: first[v] .. first[v + 1] - 1
  // (num_vertices + 1 entries).
  std::vector<int64_t> first;
  // Every corner (3 cell + corner) at a vertex with two or more copies, with the copy there;
  // ascending by corner. A corner at any other vertex v is at first[v].
  std::vector<std::pair<int64_t, int64_t>> split_corners;
  // Per vertex of the cut mesh, the vertex of the original it is a copy of (ascending).
  std::vector<int64_t> vertex_origin;
  // Vertices of the cut mesh that are copies of one original vertex: group i is
  // copies[group_offset[i] .. group_offset[i + 1]) (vertices on the cut only, 2 or more each).
  std::vector<int64_t> group_offset{0}, copies;

  // The vertex of the cut mesh at corner k of cell c.
  int64_t corner_vertex(const Topology &topology, int64_t c, int k) const;
};

//
// `split_vertices` (ascending, optional): vertices cut apart into their fans too, whether or not
// on the cut: a piece of a partitioned mesh may hold two or more fans of cells around a point it
// shares with other pieces (their cells lie between), which must be apart for its components to
// be disks (exact/reeb_pieces).
CornerCut cut_corners(const Topology &topology, std::span<const int64_t> cut_edges,
                      std::span<const int64_t> split_vertices = {});

// Every corner's vertex in the cut mesh, 3 per cell in the cells' corner order.
std::vector<int64_t> corner_vertices(const Topology &topology, const CornerCut &cut);

// Each cut edge (lo, hi) of the original as its two copies in the cut mesh, {lo1, hi1, lo2, hi2}:
// the copies at its first cell's corners, then at its second's.
std::vector<std::array<int64_t, 4>> seam_vertices(const Topology &topology, const CornerCut &cut,
                                                  std::span<const int64_t> cut_edges);

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

// Cuts `mesh` open along `cut_edges` (from cut_graph_edges), and apart at `split_vertices`
// (cut_corners). Throws hoct::Error if the result is not one disk per component, or a sphere
// (a closed component of genus 0 has an empty cut graph), as for a mesh the topology checks
// should have refused.
CutSurface cut_open(const Mesh &mesh, std::span<const int64_t> cut_edges,
                    std::span<const int64_t> split_vertices = {});

} // namespace hoct
