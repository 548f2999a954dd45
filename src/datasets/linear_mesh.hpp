// A linear (straight, flat-faced) triangle mesh: the parent mesh the dataset generators start
// from before lifting it to Lagrange cells (datasets/lagrange_mesh_builder.hpp).
#pragma once

#include "mesh/mesh_input.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

struct LinearMesh {
  std::vector<Vec3> vertices;
  // Corner ids; counter-clockwise in the plane, or with outward normals on a closed surface.
  std::vector<std::array<int64_t, 3>> triangles;
};

} // namespace hoct
