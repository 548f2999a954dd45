// The short terminal summary of a computed tree.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <string>

namespace hoct::cli {

// "tree", or "Reeb graph (2 loops)" for a Reeb graph.
std::string graph_kind(const TreeResult &tree);

// The summary's first line up to the method: "FILE: field 'f', 8 cells (max degree 3)" (taken
// before the tree, which may consume the mesh).
std::string describe_mesh(const std::string &file, const Mesh &mesh);

// The summary: `mesh_line` (describe_mesh), the method and what was computed, then the body.
void print_tree_summary(const std::string &mesh_line, const TreeResult &tree, double total_seconds);

// The summary's lines after the first (nodes, arcs, where, pairs, precision, timings).
void print_tree_body(const TreeResult &tree, double total_seconds);

// The branch decomposition, one line per branch, indented by depth, children by persistence.
void print_branches(const TreeResult &tree);

} // namespace hoct::cli
