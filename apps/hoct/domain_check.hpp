// The contour tree needs a valid mesh of a simply connected domain: one disk or one sphere.
// `--force` computes what is still well defined and labels it; what it cannot repair (a mesh
// that is not a surface, broken input data) is always refused.
#pragma once

#include "error.hpp"
#include "mesh/domain_check.hpp"
#include "mesh/mesh.hpp"

#include <set>
#include <string>
#include <vector>

namespace hoct::cli {

// Problems --force may go past: the algorithm works in each cell's reference triangle, so the
// tree of the field is defined whatever the cells' embedding (inverted, folded cells), and
// unmerged duplicate vertices only cut the surface along cracks.
inline bool forceable(const std::string &kind) {
  return kind == "inverted cell" || kind == "inverted cell (folded curved cell)" ||
         kind == "duplicate vertices";
}

// Checks the mesh for the tree. Without force, throws hoct::Error explaining the first kind of
// problem; with force, returns the reasons the result is forced (empty if none) and throws only
// for problems nothing can go past.
inline std::vector<std::string> check_domain(const Mesh &m, const std::string &file, bool force) {
  std::vector<std::string> reasons;
  std::string unforceable;
  for (const auto &[kind, p] : m.problems.kinds()) {
    if (p.severity != Severity::Error)
      continue;
    if (force && forceable(kind))
      reasons.push_back(std::to_string(p.count) + " " + kind + " (" + p.examples.front() + ")");
    else
      unforceable += kind;
  }
  if (!unforceable.empty() || (!force && m.problems.has_errors()))
    throw Error(file + ": the mesh is not valid:\n" + m.problems.summary() +
                (force ? "(--force cannot go past these: the mesh must be a surface with valid "
                         "data)"
                       : ""));
  if (!m.complete)
    throw Error(file + ": the mesh is not valid:\n" + m.problems.summary());
  const std::string why = domain_shape(m.topology);
  if (!why.empty()) {
    const std::string msg =
        file + ": the domain is not a disk or a sphere but " + why +
        "; its level-set graph is a Reeb graph (with loops), not a contour tree";
    if (!force)
      throw Error(msg + ". Use --force to compute the join/split merge anyway (one tree per "
                        "component; for holes or handles the result is not the Reeb graph).");
    reasons.push_back("the domain is not a disk or a sphere but " + why +
                      ": the join/split merge is computed (one tree per "
                      "component), not the Reeb graph");
  }
  return reasons;
}

} // namespace hoct::cli
