// A checked higher-order triangle mesh: topology, the Bernstein field and the geometry map,
// built from a MeshInput, with every problem found recorded.
#pragma once

#include "mesh/field.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh/problem_log.hpp"
#include "mesh/topology.hpp"

#include <string>

namespace hoct {

struct Mesh {
  std::string source, field_name;
  int64_t num_points = 0;
  Topology topology;
  Field field;
  Geometry geometry;
  ProblemLog problems;
  // False if the input was too broken to build topology, field and geometry.
  bool complete = false;
};

struct MeshBuildOptions {
  // Throw hoct::Error listing the problems if any error-level problem is found. With false, the
  // mesh is returned with its problems recorded (for `hoct info`), as complete as possible.
  bool throw_on_error = true;
};

Mesh build_mesh(const MeshInput &input, const MeshBuildOptions &options = {});

} // namespace hoct
