// The triangulated surface of the cube [-1, 1]^3 with a separate grid resolution per axis, the flat
// parent of closed box-like surfaces (the heater): map it with a placement onto the target surface
// (datasets/lagrange_mesh_builder.hpp).
#pragma once

#include "datasets/linear_mesh.hpp"

namespace hoct {

// Each face is an (n_b x n_c) grid of squares along its two axes, each square split into two
// triangles (alternating diagonals); vertices on cube edges and corners are shared.
// 4 (nx ny + ny nz + nz nx) triangles, outward oriented; n >= 1 each.
LinearMesh box_surface(int nx, int ny, int nz);

} // namespace hoct
