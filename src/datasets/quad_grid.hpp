// Lagrange quadrilaterals of order (p, p) on a (jittered) grid of a rectangle: the quadrilateral
// counterpart of grid_triangulation + build_lagrange_mesh, for the generators' --quads option.
#pragma once

#include "datasets/lagrange_mesh_builder.hpp"
#include "datasets/planar_triangulation.hpp"

namespace hoct {

// Every rectangle of `grid` (its `keep` must be empty) becomes one straight quadrilateral on its
// four (jittered) corners, the vertices of grid_triangulation(grid); its nodes are the bilinear
// images of (i/p, j/p), nodes of shared edges shared. Points: the (nx p + 1) x (ny p + 1) node
// grid, row by row; `value` is called once per point. Throws hoct::Error for p outside 1..10.
MeshInput build_quad_grid(const GridSpec &grid, int p, const NodeValue &value);

} // namespace hoct
