// Reader for Gmsh MSH 4.1 files (ascii and binary) with triangle elements and $NodeData.
#pragma once

#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Reads nodes, complete triangle elements of any order, and one $NodeData view (by name; empty =
// the first). Nodes are converted to canonical lattice order. Throws InputError naming the file,
// line (ascii) or byte offset (binary), and the problem.
MeshInput read_msh(const std::string &path, const std::string &scalar = "");

} // namespace hoct
