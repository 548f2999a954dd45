// The contour tree as an SVG picture: height = value, branch-decomposition layout (each branch a
// vertical segment in its own column from its extremum to its saddle, joined to its parent's
// column at the saddle's height), nodes coloured by type (maxima red, minima blue, saddles
// green) with their type, id, value and persistence as hover titles, and a value axis. A Reeb
// graph with loops, which no branch decomposition covers, is drawn as a graph: every node at its
// value, every arc (parallel ones bowed apart), the arcs on loops in orange (class "loop").
#pragma once

#include "tree/tree_result.hpp"

#include <string>

namespace hoct {

// Writes atomically. A tree must carry its branch decomposition (decompose_branches).
void write_tree_svg(const std::string &path, const TreeResult &tree, const std::string &title);

} // namespace hoct
