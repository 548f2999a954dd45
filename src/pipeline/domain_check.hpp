// A contour tree needs a valid mesh of a simply connected domain: one disk or one sphere. With
// force, what is still well defined is computed and labelled (one tree per component, the
// join/split merge where there are holes or handles; past forceable problems: inverted or folded
// cells, unmerged duplicate vertices); what nothing can go past (a mesh that is not a surface,
// broken input data) is always refused.
#pragma once

#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace hoct {

// Empty if the mesh is one disk or one sphere; else what it is instead, in words ("2 separate
// components: ...", "a non-orientable surface (like a Moebius strip): ...", "a surface with 1
// hole(s) ...", "a surface with handles ...") with its counts.
std::string domain_shape(const Topology &t);

// Throws hoct::Error listing the mesh's problems if any is one force cannot go past (or the mesh
// is incomplete); with allow_forceable false, for any error-level problem.
void require_valid_mesh(const Mesh &mesh, bool allow_forceable);

// Checks the mesh for the tree. Without force, throws hoct::Error explaining the first kind of
// problem; with force, returns the reasons the result is forced (empty if none) and throws only
// for problems nothing can go past. Messages start with the mesh's source.
std::vector<std::string> check_domain(const Mesh &mesh, bool force);

} // namespace hoct
