// The short terminal summary of a computed tree.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <string>

namespace hoct::cli {

// "tree", or "Reeb graph (2 loops)" for a Reeb graph.
std::string graph_kind(const TreeResult &tree);

void print_tree_summary(const std::string &file, const Mesh &mesh, const TreeResult &tree,
                        double total_seconds);

// The summary's lines after the first (nodes, arcs, where, pairs, precision, timings).
void print_tree_body(const TreeResult &tree, double total_seconds);

// The branch decomposition, one line per branch, indented by depth, children by persistence.
void print_branches(const TreeResult &tree);

} // namespace hoct::cli
