// Reads a mesh file of any supported format, chosen by extension (.vtu, .pvtu, .pvd, .msh).
#pragma once

#include "io/field_selection.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// field: the point-data array (VTU) or $NodeData view (MSH) and the time step (.pvd, MSH), see
// FieldSelection.
MeshInput read_mesh(const std::string &path, const FieldSelection &field = {},
                    const ReadLimits &limits = {});

} // namespace hoct
