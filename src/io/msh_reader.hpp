// Reader for Gmsh MSH files (4.1 ascii and binary, 2.2 ascii) with triangle elements and
// $NodeData. Points and lines are skipped. If several $NodeData share the chosen name, the last
// time step is used (partitions of one step are merged). Only nodes used by triangles are kept,
// in file order.
#pragma once

#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Reads nodes, complete triangle elements of any order, and one $NodeData view (by name; empty =
// the first). Nodes are converted to canonical lattice order. Throws InputError naming the file,
// line (ascii) or byte offset (binary), and the problem.
MeshInput read_msh(const std::string &path, const std::string &scalar = "");

} // namespace hoct
