// A VTK data set as hoct's mesh input: the one conversion the ParaView filter and the readers
// that go through VTK (legacy .vtk, XDMF, Exodus II, ...) share. The field is chosen by the same
// rule as hoct's own readers (io/field_selection.hpp); ghost cells and points are kept apart for
// the join of pieces (io/piece_join.hpp).
#pragma once

#include "io/field_selection.hpp"
#include "io/piece_join.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

class vtkDataArray;
class vtkDataSet;
class vtkPointData;

namespace hoct::vtkio {

// The point array `field` names in pd (name, or the default: the active scalars, else the first
// floating-point array that is no id, ghost or mask array, else the first such integer one; a
// multi-component array when field.component asks for a component or the magnitude), or null if
// there is none. *problem says why not, phrased to follow "<where>: " ("no point array named 'T'
// (point arrays: u, p)").
vtkDataArray *find_point_array(vtkPointData *pd, const FieldSelection &field, std::string *problem);

// "u, p (3 components)", or "none": the point arrays of pd, for messages.
std::string list_point_arrays(vtkPointData *pd);

// The data set's points, its triangle cells (VTK_TRIANGLE 5, VTK_QUADRATIC_TRIANGLE 22,
// VTK_LAGRANGE_TRIANGLE 69; vertex and line cells skipped), the values of `array` (component
// `component` of FieldSelection: kScalar needs one component, kMagnitude the norm) and, apart,
// the ghost levels (vtkGhostType) and global point ids (the GlobalIds attribute, or an array
// GlobalNodeId / GlobalIds / GlobalPointIds). `where` starts every message ("mesh.e, block 2").
// Throws hoct::InputError naming the cell or point for anything else (other cell types,
// non-finite coordinates or values). A piece without triangles is returned empty.
FilePiece grid_piece(vtkDataSet *data, vtkDataArray *array, int component,
                     const std::string &where);

} // namespace hoct::vtkio
