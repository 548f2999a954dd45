// Reader for Gmsh MSH files (4.1 and 2.2, ascii and binary) with triangle elements and a view:
// $NodeData, or $ElementNodeData of a continuous field (merged into node values), at one of its
// time steps. Points and lines are skipped. Only nodes used by triangles are kept, in file order.
#pragma once

#include "io/field_selection.hpp"
#include "io/file_contents.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Reads nodes, complete triangle elements of any order, and one view (by name; empty = the first
// one-component view that is no id array; a component or the magnitude of a vector view with
// field.component; a time step with field.step or field.time). Nodes are converted to canonical
// lattice order. Throws InputError naming the file, line (ascii) or byte offset (binary), and the
// problem. Counts in the file are checked against the bytes left and against `limits` before
// anything is allocated for them. With `contents`, fills it with the file's views (name, kind,
// components, time steps) once the mesh is read, before the chosen view is checked (so it is filled
// even if that fails).
MeshInput read_msh(const std::string &path, const FieldSelection &field = {},
                   const ReadLimits &limits = {}, FileContents *contents = nullptr);

// The same from the bytes of a file held in memory; `name` stands for the file in messages.
MeshInput read_msh_buffer(std::string bytes, const std::string &name,
                          const FieldSelection &field = {}, const ReadLimits &limits = {},
                          FileContents *contents = nullptr);

} // namespace hoct
