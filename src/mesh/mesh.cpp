#include "mesh/mesh.hpp"

#include "error.hpp"
#include "mesh/mesh_checks.hpp"

namespace hoct {

Mesh build_mesh(const MeshInput &input, const MeshBuildOptions &options) {
  Mesh m;
  m.source = input.source;
  m.field_name = input.field_name;
  m.num_points = static_cast<int64_t>(input.points.size());
  const bool structural_ok = check_input(input, m.problems);
  if (structural_ok) {
    m.topology = Topology::build(input, m.problems);
    m.field = Field::build(input, m.topology, m.problems);
    m.geometry = Geometry::build(input);
    check_geometry(m.geometry, m.topology, m.problems);
    m.complete = true;
  }
  if (options.throw_on_error && m.problems.has_errors())
    throw Error((input.source.empty() ? std::string("mesh") : input.source) +
                ": the mesh is not valid:\n" + m.problems.summary());
  return m;
}

} // namespace hoct
