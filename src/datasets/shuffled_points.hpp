// A mesh with its points numbered at random (the same cells, points and values): how some
// writers number them, and what a reader by parts must not assume away (io/vtu_cell_range).
#pragma once

#include "mesh/mesh_input.hpp"

#include <cstdint>

namespace hoct {

// Point i of `in` becomes point perm[i] of a random permutation drawn from `seed`.
MeshInput with_points_shuffled(const MeshInput &in, uint32_t seed);

} // namespace hoct
