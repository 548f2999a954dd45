// The native module's shared types: a mesh (its input and its built mesh), a tree, and
// contour_tree's arguments as a library request (the same one `hoct tree` makes of its flags).
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/mesh_input.hpp"
#include "pipeline/tree_request.hpp"
#include "tree/tree_result.hpp"

#include <memory>
#include <string>

namespace hoct::python {

struct PyMesh {
  MeshInput input;
  std::shared_ptr<Mesh> mesh;
};

struct PyTree {
  TreeResult tree;
};

// The arcs' paths are left to the caller (TreeRequest::arcs).
TreeRequest tree_request(const std::string &method, int refine, int threads, bool keep_flat,
                         bool force, bool augmented, const std::string &simplify);

} // namespace hoct::python
