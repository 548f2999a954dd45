// Reader for Gmsh post-processing files (.pos) in the parsed format that gmsh.view.write and
// Gmsh's "Save as .pos" produce: `View "name" { ST(x1,y1,z1, ...){v1, ...}; ... };`, scalar
// triangles of degree 1 to 3 (ST, ST2, ST3) with their values per node and time step.
#pragma once

#include "io/field_selection.hpp"
#include "io/file_contents.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Every element has its own copy of its nodes: nodes at the same position (within 1e-9 of the
// bounding-box diagonal) are merged, and must carry the same value (within 1e-9 of the view's
// range plus rounding), else the file is refused naming the point and the elements. The view is
// `field.name` (empty: the first view with scalar triangles); `field.step` / `field.time` choose
// a time step (the values of a node at the steps follow each other; TIME{...} gives the times).
// Scalar points and lines (SP, SL, SL2) and text annotations (T2, T3) are skipped; any other
// element (vectors, tensors, quadrangles, 3D) is refused naming it, as are expressions where a
// number is expected and Gmsh script commands outside a view. Throws InputError "file:LINE: what".
MeshInput read_pos(const std::string &path, const FieldSelection &field = {},
                   const ReadLimits &limits = {}, FileContents *contents = nullptr);

MeshInput read_pos_buffer(std::string bytes, const std::string &name,
                          const FieldSelection &field = {}, const ReadLimits &limits = {},
                          FileContents *contents = nullptr);

} // namespace hoct
