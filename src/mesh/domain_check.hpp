// The contour tree needs a simply connected domain: one disk or one sphere.
#pragma once

#include "mesh/topology.hpp"

#include <string>

namespace hoct {

// Empty if the mesh is one disk or one sphere; else what it is ("the domain is not a disk or a
// sphere (2 component(s), ...); its level-set graph is a Reeb graph with loops, not a contour
// tree").
std::string domain_problem(const Topology &t);

} // namespace hoct
