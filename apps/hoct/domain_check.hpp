// The contour tree needs a simply connected domain: a disk or a sphere.
#pragma once

#include "error.hpp"
#include "mesh/topology.hpp"

#include <string>

namespace hoct::cli {

// Throws hoct::Error with an explanation unless the mesh is one disk or one sphere; with
// allow_other, returns the warning text instead (empty if the domain is fine).
inline std::string check_domain(const Topology &t, const std::string &file, bool allow_other) {
  const bool disk = t.euler_characteristic() == 1 && t.boundary_loops() == 1;
  const bool sphere = t.euler_characteristic() == 2 && t.boundary_loops() == 0;
  if (t.components() == 1 && (disk || sphere))
    return "";
  const std::string msg =
      file + ": the domain is not a disk or a sphere (" + std::to_string(t.components()) +
      " component(s), Euler characteristic " + std::to_string(t.euler_characteristic()) + ", " +
      std::to_string(t.boundary_loops()) +
      " boundary loop(s)); its level-set graph is a Reeb graph with loops, not a contour tree";
  if (!allow_other)
    throw Error(msg + ". Use --allow-non-simply-connected to compute the join/split merge anyway "
                      "(the result is then not a contour tree).");
  return msg;
}

} // namespace hoct::cli
