// A reader that sits above io plugged into read_mesh: vtkio registers VTK's own readers here, so
// every front end that reads through read_mesh (the CLI, the Python module) reads their formats
// too, while io itself knows no VTK.
#pragma once

#include "io/field_selection.hpp"
#include "io/file_contents.hpp"
#include "io/read_limits.hpp"
#include "io/vtu_reader.hpp"
#include "mesh/mesh_input.hpp"

#include <functional>
#include <string>
#include <vector>

namespace hoct {

struct ExternalReader {
  std::string name;                    // "VTK 9.2", for messages
  std::vector<std::string> extensions; // lower case, with the dot, besides io's own
  std::string formats;                 // ".vtk legacy VTK, ..." for the unknown-type message
  // A whole file of one of `extensions`.
  std::function<MeshInput(const std::string &path, const FieldSelection &field,
                          const ReadLimits &limits, FileContents *contents)>
      read;
  // A .vtu (alone, or a piece of a .pvtu or .pvd) that hoct's reader refuses for its compressor
  // (VtuCompressorError: LZ4, LZMA), with the piece's bookkeeping arrays.
  std::function<MeshInput(const std::string &path, const FieldSelection &field,
                          const ReadLimits &limits, const VtuPieceRequest &request,
                          VtuPieceArrays &arrays)>
      read_vtu_piece;
};

// Registers the reader (replacing any earlier one); call at start-up, before reading on threads.
void set_external_reader(ExternalReader reader);

// The registered reader, or null.
const ExternalReader *external_reader();

} // namespace hoct
