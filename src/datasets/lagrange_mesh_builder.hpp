// Lifting a linear triangle mesh to a Lagrange mesh of degree d: one point per vertex, d-1 points
// per edge (created once per edge, keyed by its vertex pair, so both neighbouring cells use the
// same point ids), (d-1)(d-2)/2 interior points per cell; nodes in canonical lattice order
// (poly/lattice.hpp).
//
// Every node is first placed on the flat parent triangle (equispaced lattice points), then mapped
// by `place` onto the target surface: adjacent cells map the same flat edge points, so curved
// cells agree along their shared edges, and a node lies exactly on the surface if `place` does.
#pragma once

#include "datasets/linear_mesh.hpp"
#include "mesh/mesh_input.hpp"

#include <functional>

namespace hoct {

// Flat point on the parent mesh -> point on the target surface. Empty: the identity.
using NodePlacement = std::function<Vec3(const Vec3 &flat)>;
// The field at a node, from its placed position and its flat parent point.
using NodeValue = std::function<double(const Vec3 &position, const Vec3 &flat)>;

// Point ids: the parent's vertices first (same ids), then edge points edge by edge (edges ordered
// by their (lower, higher) vertex id pair, points from the lower vertex on), then interior points
// cell by cell. `place` and `value` are called once per point, possibly from several threads at
// once (they must be pure functions); the result does not depend on the number of threads.
// Throws hoct::Error for a degree outside 1..10, a corner id out of range or a repeated corner.
MeshInput build_lagrange_mesh(const LinearMesh &parent, int degree, const NodePlacement &place,
                              const NodeValue &value);

} // namespace hoct
