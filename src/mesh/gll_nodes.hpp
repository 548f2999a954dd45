// Cells whose nodes sit at Gauss-Lobatto-Legendre positions although the input labels them as
// equispaced Lagrange nodes: DOLFINx writes P >= 3 functions so (VTK's Lagrange cells have no
// other layout). Read as equispaced nodes, such a cell's field is the wrong polynomial (the
// values interpolated at the wrong reference points: hundreds of tiny spurious features); read
// as samples at their true positions, it is the solution's own.
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/mesh_input.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

// The GLL points of degree d on [0, 1], ascending (d + 1 of them; d <= kMaxDegree).
std::vector<double> gll_points(int d);

struct GllResampling {
  int64_t cells = 0;                // cells found with GLL-placed nodes (0: nothing changed)
  std::vector<CellSamples> samples; // when cells > 0: every cell's node values at their positions
  // Quadrilaterals of order >= 3 found with GLL-placed nodes: resampled in place (exactly: their
  // tensor interpolant at the equispaced nodes, values and positions; no samples needed).
  int64_t quadrilaterals = 0;
};

// Finds the straight cells of degree >= 3 whose edge nodes sit at the GLL points of their edges
// (within 1e-6 of the edge: float32 files pass) and whose other nodes lie inside. If there are
// any, returns every cell's samples (a GLL cell's node values at the reference positions of its
// nodes; any other cell's at its lattice) and moves the GLL cells' nodes onto the equispaced
// lattice of their straight triangle, so that the geometry is the straight cell it is; else
// changes nothing. Build the mesh with build_mesh_from_samples(input, r.samples).
GllResampling resample_gll_cells(MeshInput &input);

} // namespace hoct
