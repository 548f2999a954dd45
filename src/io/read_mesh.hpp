// Reads a mesh file of any supported format, chosen by extension (.vtu, .msh).
#pragma once

#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// scalar: name of the point-data array (VTU) or $NodeData view (MSH); empty = the first one.
MeshInput read_mesh(const std::string &path, const std::string &scalar = "",
                    const ReadLimits &limits = {});

} // namespace hoct
