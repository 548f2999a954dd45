// The shape of a surface cut into pieces (one per MPI rank), from what each piece tells of itself:
// its counts (vertices, edges, triangles, components, closed boundary loops) and its seam band,
// the triangles at its open points (the points other pieces use too). Glued together, the
// summaries give the whole surface's Euler characteristic, boundary loops, components and
// orientability, and check the whole's fans at every open point (each open point's triangles, from
// every piece, must form one fan: no edge of more than two triangles, no pinch) without the
// whole mesh: what crosses is the seams, not the mesh. With each piece's own topology checked
// (Topology::build with its open points), a clean glue proves the whole mesh has no
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

struct PieceSurface {
  int32_t piece = 0;
  int64_t vertices = 0, edges = 0, triangles = 0, components = 0;
  int64_t closed_loops = 0; // boundary loops of the piece with no open point
  bool orientable = true;
  std::vector<BandTriangle> band;
  std::vector<LoopEnd> loop_ends;
};

// The summary of one piece: `topology` its triangles' (built with `open_points`), `global_point`
// the whole's id of each of its points, `open_points` a flag per point (shared with other
// pieces); `threads` for the passes over the piece (the same summary for any count).
PieceSurface summarize_piece(const Topology &topology, std::span<const int64_t> global_point,
                             std::span<const uint8_t> open_points, int32_t piece, int threads = 1);

struct SurfaceShape {
  int64_t components = 0, euler_characteristic = 0, boundary_loops = 0;
  bool orientable = true;
  // Empty when every open point's triangles form one fan; else what is wrong, at one point.
  std::string seam_problem;
};

// The whole surface from every piece's summary (in any order).
SurfaceShape glue_pieces(const std::vector<PieceSurface> &pieces);

// Byte form of a summary, for sending it.
std::vector<std::byte> encode_piece_surface(const PieceSurface &s);
PieceSurface decode_piece_surface(std::span<const std::byte> bytes);

} // namespace hoct
