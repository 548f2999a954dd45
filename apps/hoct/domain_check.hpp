// The contour tree needs a simply connected domain: a disk or a sphere.
#pragma once

#include "error.hpp"
#include "mesh/domain_check.hpp"
#include "mesh/topology.hpp"

#include <string>

namespace hoct::cli {

// Throws hoct::Error with an explanation unless the mesh is one disk or one sphere; with
// allow_other, returns the warning text instead (empty if the domain is fine).
inline std::string check_domain(const Topology &t, const std::string &file, bool allow_other) {
  const std::string problem = domain_problem(t);
  if (problem.empty())
    return "";
  const std::string msg = file + ": " + problem;
  if (!allow_other)
    throw Error(msg + ". Use --allow-non-simply-connected to compute the join/split merge anyway "
                      "(the result is then not a contour tree).");
  return msg;
}

} // namespace hoct::cli
