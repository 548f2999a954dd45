// Exodus II files (MOOSE, Cubit, SEACAS tools) read with the Exodus library (VTK's copy,
// vtkexodusII): coordinates and nodal variables as doubles, the element blocks' connectivity as
// the file holds it (one global node numbering: no joining). Blocks of TRI3 / TRI6 elements are
// linear / quadratic Lagrange triangles; TRI7 (P2 plus the cubic bubble 27 l0 l1 l2, MOOSE's
// second-order triangle) is exactly a cubic, and is read as one: its ten cubic nodes are the
// TRI7 interpolant (field and isoparametric map) at the cubic lattice points. Nodal variables
// are scalars; `--component` takes NAME_x / NAME_y / NAME_z, `magnitude` their norm. Time steps
// by --step / --time. Before the library reads anything, exodus_blocks checks that every
// variable ends inside the file.
#pragma once

#include "io/field_selection.hpp"
#include "io/file_contents.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Throws InputError naming the file (and block, variable or step) for what it cannot read.
MeshInput read_exodus(const std::string &path, const FieldSelection &field,
                      const ReadLimits &limits, FileContents *contents);

} // namespace hoct
