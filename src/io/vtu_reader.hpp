// Reader for VTK XML UnstructuredGrid (.vtu) files with triangle cells of any Lagrange degree.
#pragma once

#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Reads points, triangle cells (VTK_TRIANGLE 5, VTK_QUADRATIC_TRIANGLE 22,
// VTK_LAGRANGE_TRIANGLE 69) and one scalar point-data array (by name; empty = the first).
// Nodes are converted to canonical lattice order. Throws InputError naming the file and the
// problem for any malformed or unsupported input.
MeshInput read_vtu(const std::string &path, const std::string &scalar = "");

} // namespace hoct
