#include "pipeline/domain_check.hpp"

#include "util/error.hpp"

namespace hoct {
namespace {

std::string name_of(const Mesh &m) { return m.source.empty() ? "the mesh" : m.source; }

} // namespace

std::string domain_shape(const Topology &t) {
  SurfaceShape s;
  s.components = t.components();
  s.euler_characteristic = t.euler_characteristic();
  s.boundary_loops = t.boundary_loops();
  s.orientable = t.orientable();
  return domain_shape(s);
}

std::string domain_shape(const SurfaceShape &s) {
  const bool disk = s.euler_characteristic == 1 && s.boundary_loops == 1;
  const bool sphere = s.euler_characteristic == 2 && s.boundary_loops == 0;
  if (s.components == 1 && (disk || sphere))
    return "";
  std::string why;
  if (s.components > 1)
    why = std::to_string(s.components) + " separate components";
  else if (!s.orientable)
    why = "a non-orientable surface (like a Moebius strip)";
  else if (s.boundary_loops > 1)
    why = "a surface with " + std::to_string(s.boundary_loops - 1) + " hole(s) (" +
          std::to_string(s.boundary_loops) + " boundary loops, like an annulus)";
  else
    why = "a surface with handles (genus > 0)";
  return why + ": " + std::to_string(s.components) + " component(s), Euler characteristic " +
         std::to_string(s.euler_characteristic) + ", " + std::to_string(s.boundary_loops) +
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
