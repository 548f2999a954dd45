// A contour tree as VTK PolyData (.vtp) for ParaView: nodes as vertices and arcs as lines (the
// polylines of TreeResult::arc_paths when present, drawn on the surface; else straight), with
// point arrays "type" (0 minimum, 1 maximum, 2 saddle, 3 regular), "value", "persistence" (the
// largest persistence of a pair the node belongs to, 0 if none), "node_id", "cell" and
// "location" (0 vertex, 1 edge, 2 interior, 3 unknown), "fallback" (1 where a degenerate cell
// fell back to the PL rule), and cell arrays "persistence" (of the
// arc's lower/upper pair, the smaller node persistence) for the lines.
#pragma once

#include "tree/tree_result.hpp"

#include <string>

namespace hoct {

// Writes atomically (temporary file, then rename).
void write_tree_vtp(const std::string &path, const TreeResult &tree);

} // namespace hoct
