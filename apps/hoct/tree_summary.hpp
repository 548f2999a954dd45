// The short terminal summary of a computed tree.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <string>

namespace hoct::cli {

// `time_step_detail`: which step of a file of several was read (LoadedMesh), after the field.
void print_tree_summary(const std::string &file, const Mesh &mesh, const TreeResult &tree,
                        double total_seconds, const std::string &time_step_detail = {});

// The branch decomposition, one line per branch, indented by depth, children by persistence.
void print_branches(const TreeResult &tree);

} // namespace hoct::cli
