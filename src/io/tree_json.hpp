// The contour-tree JSON format every tree hoct writes shares:
//   {"format": "hoct-contour-tree", "version": 1, "method", "augmented",
//    "input": {"points", "cells", "field", "fingerprint": 16 hex digits} (the mesh the tree was
//    computed from: mesh/mesh_fingerprint.hpp; absent in files of earlier versions),
//    "forced": true and "forced_reasons": [...] (only for hoct tree --force on an invalid domain),
//    "nodes": [{"id", "type", "value", "position": [x,y,z], "cell", "uv": [u,v], "location",
//               "fallback", "merged" (only if > 1: the nodes of a flat region it stands for)}],
//    "arcs": [[id, id], ...], "pairs": [{"birth", "death", "persistence", "kind"}],
//    "branches": [{"id", "extremum", "saddle", "persistence", "parent", "depth"}],
//    "stats": {"nodes_by_type": {...}, "nodes_by_location": {...}, <named statistics>}}
// Node ids are indices into "nodes", which are ascending in the total order (value, id).
#pragma once

#include "tree/tree_result.hpp"

#include <string>

namespace hoct {

// Writes atomically (temporary file, then rename). Without `timings` the time_* statistics are
// left out: the same tree then gives the same bytes, whatever the threads or the front end.
// The arrays are streamed to the file as they are formatted, long ones on `threads` threads
// (the same text for any number).
void write_tree_json(const std::string &path, const TreeResult &tree, bool timings = true,
                     int threads = 1);
// The same text as write_tree_json writes: the header's fields and "stats" one per line, each
// node, arc, pair and branch compact on a line of its own.
std::string tree_to_json(const TreeResult &tree, bool timings = true, int threads = 1);

// Reads a file written by write_tree_json; throws InputError naming the file and the problem.
TreeResult read_tree_json(const std::string &path);

} // namespace hoct
