#include "mesh/domain_check.hpp"

namespace hoct {

std::string domain_problem(const Topology &t) {
  const bool disk = t.euler_characteristic() == 1 && t.boundary_loops() == 1;
  const bool sphere = t.euler_characteristic() == 2 && t.boundary_loops() == 0;
  if (t.components() == 1 && (disk || sphere))
    return "";
  return "the domain is not a disk or a sphere (" + std::to_string(t.components()) +
         " component(s), Euler characteristic " + std::to_string(t.euler_characteristic()) + ", " +
         std::to_string(t.boundary_loops()) +
         " boundary loop(s)); its level-set graph is a Reeb graph with loops, not a contour tree";
}

} // namespace hoct
