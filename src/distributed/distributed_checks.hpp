// The whole mesh's checks made by its pieces (one per rank) together, with no rank holding the
// whole: what crosses between ranks is the seams' triangles and the vertices' positions.
#pragma once

#include "mesh/mesh_input.hpp"
#include "mesh/piece_surface.hpp"

#include <mpi.h>

#include <cstdint>
#include <span>

namespace hoct {

// Collective: every rank's piece summary (`own`, null for a rank without cells) glued on rank 0,
// which gets the whole surface's shape (the other ranks an empty one).
SurfaceShape gather_surface(MPI_Comm comm, const PieceSurface *own);

// Collective: whether any two vertices of different ids on different ranks lie within
// `tolerance` (Euclidean) of each other, the same answer on every rank (each rank checks its own
// vertices among themselves: mesh_checks). A coarse grid over `box` (the whole's bounding box)
// first tells which regions hold vertices of several ranks (one sum of occupancy counts over
// the ranks); only the vertices there are sent, to the ranks owning the fine grid cells (of 64
// tolerances) their tolerance box meets, which compare what they receive.
bool duplicate_vertices_across(MPI_Comm comm, std::span<const Vec3> positions,
                               std::span<const int64_t> ids, double tolerance,
                               const std::array<Vec3, 2> &box, int threads = 1);

} // namespace hoct
