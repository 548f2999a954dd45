// Reads a mesh file of any supported format, chosen by extension (.vtu, .pvtu, .pvd, .msh,
// .pos).
#pragma once

#include "io/field_selection.hpp"
#include "io/file_contents.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// field: the point-data array (VTU) or $NodeData / $ElementNodeData view (MSH) and the time
// step (.pvd, MSH), see FieldSelection. `contents`, if given, receives the fields the file
// offers where the reader lists them (Gmsh views with their time steps; empty for other
// formats).
MeshInput read_mesh(const std::string &path, const FieldSelection &field = {},
                    const ReadLimits &limits = {}, FileContents *contents = nullptr);

} // namespace hoct
