// Mesh files read through VTK's own readers (Debian's ParaView/VTK libraries): the formats hoct's
// fast readers (io/) do not read. Each block or piece of the data VTK gives is converted by
// vtkio/grid_input and the blocks joined (io/piece_join): by global point ids where every block
// has them (Exodus II's GlobalNodeId), else by position.
#pragma once

#include "io/field_selection.hpp"
#include "io/file_contents.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <string>
#include <vector>

namespace hoct::vtkio {

struct VtkFormat {
  std::vector<std::string> extensions; // lower case, with the dot
  std::string description;             // "legacy VTK (vtkDataSetReader)"
};

// The formats read through VTK, in the order the help lists them.
const std::vector<VtkFormat> &vtk_formats();

// Reads the file with VTK's reader for its extension (a .vtu through vtkXMLUnstructuredGridReader:
// the compressors hoct's reader lacks). The field and time step follow `field`
// (MeshInput::field_detail names the step of a file with several); `contents`, if given, receives
// the point arrays and time steps. VTK's errors become hoct::InputError "<path>: ..." with VTK's
// message; a file with no surface cells, or no point array to read, is an error that says what
// the file holds.
MeshInput read_vtk_file(const std::string &path, const FieldSelection &field = {},
                        const ReadLimits &limits = {}, FileContents *contents = nullptr);

} // namespace hoct::vtkio

namespace hoct::vtkio {

// Plugs read_vtk_file into io's read_mesh (io/external_reader.hpp) for the formats above and for
// .vtu files (alone or pieces of a .pvtu / .pvd) whose compressor hoct's reader lacks.
void register_vtk_reader();

} // namespace hoct::vtkio
