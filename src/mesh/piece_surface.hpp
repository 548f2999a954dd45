// The shape of a surface cut into pieces (one per MPI rank), from what each piece tells of itself:
// its counts (vertices, edges, triangles, components, closed boundary loops) and its seam band,
// the triangles at its open points (the points other pieces use too). Merged pairwise, in a
// binary tree over consecutive pieces as the ranks merge their kept trees, the summaries give
// the whole surface's Euler characteristic, boundary loops, components and orientability, and
// check the whole's fans at every open point (each open point's triangles, from every piece,
// must form one fan: no edge of more than two triangles, no pinch) without the whole mesh. A
// merge settles the points whose pieces it holds all (their span over the pieces), and keeps of
// the band only the triangles at points still open: what crosses is the groups' borders, not the
// mesh, nor every piece's seams on one rank. With each piece's own topology checked
// (Topology::build with its open points), a clean merge proves the whole mesh has no
// non-manifold edge or vertex, and its shape is the one computed.
#pragma once

#include "mesh/topology.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hoct {

// A triangle with an open corner, named by the whole's point ids.
struct BandTriangle {
  std::array<int64_t, 3> point{}; // the corners in the triangle's order
  int64_t component = 0;          // its component's label in the piece
  int32_t piece = 0;
  int8_t parity = 1; // Topology::cell_parity
  uint8_t open = 0;  // bit k: corner k is an open point
  uint8_t pad[2] = {};
};

// An open point on a piece's boundary run: the run's label in the piece (the runs are the
// components of the piece's boundary edges that have a point only this piece uses).
struct LoopEnd {
  int64_t point = 0;
  int64_t run = 0;
  int32_t piece = 0;
  int32_t pad = 0;
};

// An open point, with the first and the last piece whose cells use it.
struct OpenPoint {
  int64_t point = 0;
  int32_t first = 0, last = 0;
};

// The summary of the pieces [piece, last_piece].
struct PieceSurface {
  int32_t piece = 0, last_piece = 0;
  int64_t vertices = 0, edges = 0, triangles = 0, components = 0;
  int64_t closed_loops = 0; // boundary loops with no open point
  bool orientable = true;
  std::vector<BandTriangle> band; // the triangles with a corner at a point still open
  std::vector<LoopEnd> loop_ends; // runs of boundary edges ending at points still open
  std::vector<OpenPoint> open;    // the points still open, ascending
  std::string problem;            // the first problem a merge found (empty if none)
};

// The summary of one piece: `topology` its triangles' (built with its open points),
// `global_point` the whole's id of each of its points, `spans` the first and last piece using
// each of its points (open where they differ); `threads` for the passes over the piece (the
// same summary for any count).
PieceSurface summarize_piece(const Topology &topology, std::span<const int64_t> global_point,
                             std::span<const std::array<int32_t, 2>> spans, int32_t piece,
                             int threads = 1);
// The summary of a piece without cells (an idle rank's).
PieceSurface empty_piece_surface(int32_t piece);

// The summary of the pieces [a.piece, b.last_piece] from those of [a.piece, a.last_piece] and
// [b.piece = a.last_piece + 1, b.last_piece]: the points whose span lies in it settled (their
// fans checked; the edges at them shared, or on the whole's boundary; their boundary runs
// joined), the rest kept for the next merge.
PieceSurface merge_piece_surfaces(const PieceSurface &a, const PieceSurface &b);

struct SurfaceShape {
  int64_t components = 0, euler_characteristic = 0, boundary_loops = 0;
  bool orientable = true;
  // Empty when every open point's triangles form one fan; else what is wrong, at one point.
  std::string seam_problem;
};

// The shape of the whole from the summary of all pieces (every point settled).
SurfaceShape surface_shape(const PieceSurface &all);

// The whole surface from every piece's summary (in any order; the pieces without cells may be
// missing): merged pairwise in a binary tree over the pieces, as the ranks merge them.
SurfaceShape glue_pieces(std::vector<PieceSurface> pieces);

// Byte form of a summary, for sending it.
std::vector<std::byte> encode_piece_surface(const PieceSurface &s);
PieceSurface decode_piece_surface(std::span<const std::byte> bytes);

} // namespace hoct
