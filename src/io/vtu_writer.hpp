// Writer for VTK XML UnstructuredGrid (.vtu): the mesh as Lagrange triangles (VTK_TRIANGLE for
// degree 1, VTK_LAGRANGE_TRIANGLE = 69 otherwise) with the scalar as point data. ParaView opens it.
#pragma once

#include "io/vtk_xml_arrays.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

namespace hoct {

// Writes atomically (io/atomic_file.hpp). Point data holds the scalar under mesh.field_name
// (or "f" if empty). Nodes are written in VTK order.
void write_vtu(const std::string &path, const MeshInput &mesh,
               VtkEncoding encoding = VtkEncoding::AppendedRaw);

} // namespace hoct
