// Reader for VTK XML UnstructuredGrid (.vtu) files with triangle cells of any Lagrange degree.
#pragma once

#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Reads points, triangle cells (VTK_TRIANGLE 5, VTK_QUADRATIC_TRIANGLE 22,
// VTK_LAGRANGE_TRIANGLE 69) and one scalar point-data array (by name; empty = the first).
// Nodes are converted to canonical lattice order. Throws InputError naming the file and the
// problem for any malformed or unsupported input. Counts in the file are checked against the
// bytes it has and against `limits` before anything is allocated for them.
MeshInput read_vtu(const std::string &path, const std::string &scalar = "",
                   const ReadLimits &limits = {});

// The same from the bytes of a file held in memory; `name` stands for the file in messages.
MeshInput read_vtu_buffer(std::string bytes, const std::string &name,
                          const std::string &scalar = "", const ReadLimits &limits = {});

} // namespace hoct
