// The level-set graph needs a valid mesh of a surface. On one disk or one sphere it is the
// contour tree; on any other surface (holes, handles, a twist, several components) every method
// computes the Reeb graph (mesh/cut_surface, pl/pl_cut), so the domain's shape is no problem.
// With force, what is still well defined is computed past forceable problems (inverted or
// folded cells, unmerged duplicate vertices) and labelled; what nothing can go past (a mesh that
// is not a surface, broken input data) is always refused.
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/piece_surface.hpp"

#include <string>
#include <vector>

namespace hoct {

// Empty if the mesh is one disk or one sphere; else what it is instead, in words ("2 separate
// components: ...", "a non-orientable surface (like a Moebius strip): ...", "a surface with 1
// hole(s) ...", "a surface with handles ...") with its counts.
std::string domain_shape(const Topology &t);
// The same from a surface's counts (a distributed mesh's, mesh/piece_surface).
std::string domain_shape(const SurfaceShape &s);

// Throws hoct::Error listing the mesh's problems if any is one force cannot go past (or the mesh
// is incomplete); with allow_forceable false, for any error-level problem.
void require_valid_mesh(const Mesh &mesh, bool allow_forceable);

// Checks the mesh for the tree. Without force, throws hoct::Error explaining the first kind of
// problem; with force, returns the reasons the result is forced (empty if none) and throws only
// for problems nothing can go past. Messages start with the mesh's source.
std::vector<std::string> check_domain(const Mesh &mesh, bool force);

} // namespace hoct
