// Reader for Gmsh MSH files (4.1 ascii and binary, 2.2 ascii) with triangle elements and
// $NodeData. Points and lines are skipped. If several $NodeData share the chosen name, the last
// time step is used (partitions of one step are merged). Only nodes used by triangles are kept,
// in file order.
#pragma once

#include "io/field_selection.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Reads nodes, complete triangle elements of any order, and one $NodeData view (by name; empty =
// the first one-component view that is no id array; a component or the magnitude of a vector
// view with field.component). Nodes are converted to canonical lattice order. Throws InputError
// naming the file, line (ascii) or byte offset (binary), and the problem. Counts in the file are
// checked against the bytes left and against `limits` before anything is allocated for them.
MeshInput read_msh(const std::string &path, const FieldSelection &field = {},
                   const ReadLimits &limits = {});

// The same from the bytes of a file held in memory; `name` stands for the file in messages.
MeshInput read_msh_buffer(std::string bytes, const std::string &name,
                          const FieldSelection &field = {}, const ReadLimits &limits = {});

} // namespace hoct
