// Shared by the commands: read a file and build the checked mesh, timing both.
#pragma once

#include "mesh/mesh.hpp"

#include <string>

namespace hoct::cli {

struct LoadedMesh {
  MeshInput input; // as read (Lagrange nodes), for the commands that need the nodes themselves
  Mesh mesh;
  double read_seconds = 0, build_seconds = 0;
};

// Reads `path` (any supported format) and builds the mesh. With strict = true, any error-level
// problem throws hoct::Error listing them.
LoadedMesh load_mesh(const std::string &path, const std::string &scalar, bool strict);

} // namespace hoct::cli
