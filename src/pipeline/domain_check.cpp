#include "pipeline/domain_check.hpp"

#include "util/error.hpp"

namespace hoct {
namespace {

std::string name_of(const Mesh &m) { return m.source.empty() ? "the mesh" : m.source; }

} // namespace

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

void require_valid_mesh(const Mesh &m, bool allow_forceable) {
  bool unforceable = false;
  for (const auto &[kind, p] : m.problems.kinds())
    if (p.severity == Severity::Error && !(allow_forceable && problem_info(kind).forceable))
      unforceable = true;
  if (unforceable || !m.complete)
    throw Error(name_of(m) + ": the mesh is not valid:\n" + m.problems.summary() +
                (allow_forceable && m.complete
                     ? "(--force (Python: force=True; ParaView: Force) cannot go past these: the "
                       "mesh must be a surface with valid data)"
                     : ""));
}

std::vector<std::string> check_domain(const Mesh &m, bool force) {
  require_valid_mesh(m, force);
  std::vector<std::string> reasons;
  for (const auto &[kind, p] : m.problems.kinds())
    if (p.severity == Severity::Error) // forceable, and forced (else thrown above)
      reasons.push_back(std::to_string(p.count) + " " + to_string(kind) + " (" +
                        p.examples.front() + ")");
  return reasons;
}

} // namespace hoct
