// The subdivided icosahedron: every face of a regular icosahedron (corners on the unit sphere)
// split into n^2 congruent flat triangles. The vertices stay on the flat faces: the icosphere
// is the flat parent of a sphere mesh, and a placement such as p / |p| puts the Lagrange nodes
// on the sphere (datasets/lagrange_mesh_builder.hpp).
#pragma once

#include "datasets/linear_mesh.hpp"

namespace hoct {

// 20 n^2 triangles, 10 n^2 + 2 vertices, outward oriented; n >= 1.
LinearMesh icosphere(int n);

// The n >= 1 for which 20 n^2 is closest to `cells`.
int icosphere_subdivision(long long cells);

} // namespace hoct
