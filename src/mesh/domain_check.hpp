// The contour tree needs a simply connected domain: one disk or one sphere.
#pragma once

#include "mesh/topology.hpp"

#include <string>

namespace hoct {

// Empty if the mesh is one disk or one sphere; else a sentence: "the domain is not a disk or a
// sphere but <domain_shape>; its level-set graph is a Reeb graph (with loops), not a contour
// tree".
std::string domain_problem(const Topology &t);

// Empty if the mesh is one disk or one sphere; else what it is instead, in words ("2 separate
// components: ...", "a non-orientable surface (like a Moebius strip): ...", "a surface with 1
// hole(s) ...", "a surface with handles ...") with its counts.
std::string domain_shape(const Topology &t);

} // namespace hoct
