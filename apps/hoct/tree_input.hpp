// The commands that read a tree with its mesh (render --tree, check) make sure it is that mesh's
// tree: the input fingerprint the tree file records (util/fingerprint.hpp) against the mesh's.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <string>

namespace hoct::cli {

// Throws hoct::Error when the tree at `tree_path` records another input than `mesh` (read from
// `mesh_path`), naming both and the command's `options` that select the mesh and its field
// (e.g. "--scalar"); warns on stderr when the tree records none (a file of an earlier
// version) and accepts it.
void require_tree_of_mesh(const std::string &tree_path, const TreeResult &tree,
                          const std::string &mesh_path, const Mesh &mesh,
                          const std::string &options);

} // namespace hoct::cli
