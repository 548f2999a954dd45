// Reader for VTK XML UnstructuredGrid (.vtu) files with triangle cells of any Lagrange degree.
#pragma once

#include "io/field_selection.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Reads points, triangle cells (VTK_TRIANGLE 5, VTK_QUADRATIC_TRIANGLE 22,
// VTK_LAGRANGE_TRIANGLE 69) and the point-data field `field` selects (a one-component array, or
// a component or the magnitude of a vector one; by default the active scalars, else the first
// floating-point array that is no id, ghost or mask array). Empty pieces are skipped.
// Nodes are converted to canonical lattice order. Throws InputError naming the file and the
// problem for any malformed or unsupported input. Counts in the file are checked against the
// bytes it has and against `limits` before anything is allocated for them.
MeshInput read_vtu(const std::string &path, const FieldSelection &field = {},
                   const ReadLimits &limits = {});

// The same from the bytes of a file held in memory; `name` stands for the file in messages.
MeshInput read_vtu_buffer(std::string bytes, const std::string &name,
                          const FieldSelection &field = {}, const ReadLimits &limits = {});

} // namespace hoct
