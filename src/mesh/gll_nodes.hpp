// Cells whose nodes sit at Gauss-Lobatto-Legendre positions although the input labels them as
// equispaced Lagrange nodes: DOLFINx writes P >= 3 functions so (VTK's Lagrange cells have no
// other layout). Read as equispaced nodes, such a cell's field is the wrong polynomial (the
// values interpolated at the wrong reference points: hundreds of tiny spurious features); read
// as samples at their true positions, it is the solution's own.
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/mesh_input.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

// The GLL points of degree d on [0, 1], ascending (d + 1 of them; d <= kMaxDegree).
std::vector<double> gll_points(int d);

struct GllResampling {
  // Triangles found with GLL-placed nodes, resampled in place: their nodes moved onto the
  // equispaced lattice of their straight triangle, with the values there of the polynomial
  // through their samples (its values at the nodes' true positions).
  int64_t cells = 0;
  // Quadrilaterals of order >= 3 found with GLL-placed nodes, resampled in place: their tensor
  // interpolant at the equispaced nodes, values and positions.
  int64_t quadrilaterals = 0;
};

// Finds the straight triangles of degree >= 3 whose edge nodes sit at the GLL points of their
// edges (within 1e-6 of the edge: float32 files pass) and whose other nodes lie inside, and the
// quadrilaterals of order >= 3 whose edge nodes sit at the GLL points of their straight edges,
// and resamples them in place (see GllResampling); changes nothing else. An edge's nodes get
// the same bits from every cell around it, computed from the edge's own nodes (so that the pieces
// of a partitioned mesh, each resampled alone, agree with the whole resampled at once). Throws
// hoct::Error naming the cell whose samples give no polynomial (ill-conditioned). Mesh's
// fingerprint: of the data as read, when the input records it (MeshInput::read_fingerprint).
GllResampling resample_gll_cells(MeshInput &input);

// What the front ends tell the user of a resampling (none for nothing resampled): "N cell(s)
// have their nodes at Gauss-Lobatto-Legendre points ...", one sentence per kind of cell.
std::vector<std::string> gll_notes(const GllResampling &resampled);

} // namespace hoct
