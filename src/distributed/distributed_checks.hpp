// The whole mesh's checks made by its pieces (one per rank) together, with no rank holding the
// whole: what crosses between ranks is the seams' triangles and the vertices' positions.
#pragma once

#include "mesh/mesh_input.hpp"
#include "mesh/piece_surface.hpp"

#include <mpi.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// Collective: every rank's piece summary (`own`; empty_piece_surface for a rank without cells)
// merged pairwise in a binary tree over the ranks (rank r takes in r + 1, r + 2, r + 4, ... while
// r is a multiple of twice the step): rank 0 gets the whole surface's shape (the other ranks an
// empty one). A group's message is its border's band, not every piece's.
SurfaceShape merge_surfaces(MPI_Comm comm, PieceSurface own);

// Collective: whether any two vertices of different ids on different ranks lie within
// `tolerance` (Euclidean) of each other, the same answer on every rank (each rank checks its own
// vertices among themselves: mesh_checks). A coarse grid over `box` (the whole's bounding box)
// first tells which regions hold vertices of several ranks (one sum of occupancy counts over
// the ranks); only the vertices there are sent, to the ranks owning the fine grid cells (of 64
// tolerances) their tolerance box meets, which compare what they receive.
bool duplicate_vertices_across(MPI_Comm comm, std::span<const Vec3> positions,
                               std::span<const int64_t> ids, double tolerance,
                               const std::array<Vec3, 2> &box, int threads = 1);

// Grids over the whole's bounding box for finding points within a tolerance of each other across
// ranks: coarse cells (about 256 along the box's longest side) tell where points of different
// labels (ranks, file pieces) meet; fine cells (64 tolerances) are owned by ranks, each point
// sent to the owners of the fine cells its box of three tolerances meets (one, near a face up to
// eight): any two points within two tolerances of each other meet at the owner of either one's
// cell, whatever the rounding.
class ToleranceGrid {
public:
  ToleranceGrid(const std::array<Vec3, 2> &box, double tolerance);
  // Collective: per point, whether its coarse cells hold points of another label too (on any
  // rank). Point i's label is base + label[i] (or base alone for an empty `label`), the points
  // of one label consecutive.
  std::vector<uint8_t> near_other_labels(MPI_Comm comm, std::span<const Vec3> positions,
                                         int64_t base, std::span<const uint32_t> label) const;
  // The distinct ranks owning the fine cells p's box meets, into `to`; returns how many.
  int fine_owners(const Vec3 &p, int ranks, int to[8]) const;
  // The rank owning the fine cell p lies in (one of fine_owners(p)).
  int home_owner(const Vec3 &p, int ranks) const {
    int owner_rank = 0;
    for_cells(p, inv_fine_, 0.0,
              [&](int64_t i, int64_t j, int64_t k) { owner_rank = fine_owner(i, j, k, ranks); });
    return owner_rank;
  }

private:
  // At most 258 coarse cells a side (the boxes reach one beyond): dense keys.
  static constexpr uint64_t kSide = 260, kCoarseCells = kSide * kSide * kSide;
  static uint64_t mix(uint64_t x) {
    x ^= x >> 31;
    x *= 0x9e3779b97f4a7c15ull;
    x ^= x >> 29;
    x *= 0xd6e8feb86659fd93ull;
    return x ^ (x >> 32);
  }
  static int owner(uint64_t key, int ranks) {
    return static_cast<int>(mix(key) % static_cast<uint64_t>(ranks));
  }
  static int fine_owner(int64_t i, int64_t j, int64_t k, int ranks) {
    return owner(mix(static_cast<uint64_t>(i)) ^ mix(static_cast<uint64_t>(j) + 1) ^
                     mix(static_cast<uint64_t>(k) + 2),
                 ranks);
  }
  // floor(x) for |x| < 2^62 (std::floor is a library call without SSE4.1).
  static int64_t floor_int(double x) {
    const int64_t i = static_cast<int64_t>(x);
    return i - (x < static_cast<double>(i));
  }
  template <class F> void for_cells(const Vec3 &p, double inverse, double reach, F &&f) const {
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = floor_int((p[a] - origin_[a] - reach) * inverse);
      hi[a] = floor_int((p[a] - origin_[a] + reach) * inverse);
    }
    for (int64_t i = lo[0]; i <= hi[0]; ++i)
      for (int64_t j = lo[1]; j <= hi[1]; ++j)
        for (int64_t k = lo[2]; k <= hi[2]; ++k)
          f(i, j, k);
  }
  template <class F> void for_coarse(const Vec3 &p, F &&f) const {
    for_cells(p, inv_coarse_, reach_, [&](int64_t i, int64_t j, int64_t k) {
      f((static_cast<uint64_t>(i + 1) * kSide + static_cast<uint64_t>(j + 1)) * kSide +
        static_cast<uint64_t>(k + 1));
    });
  }

  Vec3 origin_;
  double reach_, inv_coarse_, inv_fine_;
};

} // namespace hoct
