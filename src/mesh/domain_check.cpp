#include "mesh/domain_check.hpp"

namespace hoct {

std::string domain_shape(const Topology &t) {
  const bool disk = t.euler_characteristic() == 1 && t.boundary_loops() == 1;
  const bool sphere = t.euler_characteristic() == 2 && t.boundary_loops() == 0;
  if (t.components() == 1 && (disk || sphere))
    return "";
  std::string why;
  if (t.components() > 1)
    why = std::to_string(t.components()) + " separate components";
  else if (!t.orientable())
    why = "a non-orientable surface (like a Moebius strip)";
  else if (t.boundary_loops() > 1)
    why = "a surface with " + std::to_string(t.boundary_loops() - 1) + " hole(s) (" +
          std::to_string(t.boundary_loops()) + " boundary loops, like an annulus)";
  else
    why = "a surface with handles (genus > 0)";
  return why + ": " + std::to_string(t.components()) + " component(s), Euler characteristic " +
         std::to_string(t.euler_characteristic()) + ", " + std::to_string(t.boundary_loops()) +
         " boundary loop(s)";
}

std::string domain_problem(const Topology &t) {
  const std::string why = domain_shape(t);
  if (why.empty())
    return "";
  return "the domain is not a disk or a sphere but " + why +
         "; its level-set graph is a Reeb graph (with loops), not a contour tree";
}

} // namespace hoct
