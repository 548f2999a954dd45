// Reader for VTK XML UnstructuredGrid (.vtu) files with triangle cells of any Lagrange degree.
#pragma once

#include "io/field_selection.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"
#include "util/error.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

// Reads points, triangle cells (VTK_TRIANGLE 5, VTK_QUADRATIC_TRIANGLE 22,
// VTK_LAGRANGE_TRIANGLE 69) and the point-data field `field` selects (a one-component array, or
// a component or the magnitude of a vector one; by default the active scalars, else the first
// floating-point array that is no id, ghost or mask array). Empty pieces are skipped.
// Nodes are converted to canonical lattice order. Throws InputError naming the file and the
// problem for any malformed or unsupported input. Counts in the file are checked against the
// bytes it has and against `limits` before anything is allocated for them.
// A file with ghost cells or points (vtkGhostType: one piece of a partitioned output) is read
// whole, its ghost cells kept, with a warning in MeshInput::warnings that its tree is not the
// whole domain's (naming the .pvtu beside it that lists it, if there is one).
MeshInput read_vtu(const std::string &path, const FieldSelection &field = {},
                   const ReadLimits &limits = {});

// The same from the bytes of a file held in memory; `name` stands for the file in messages.
MeshInput read_vtu_buffer(std::string bytes, const std::string &name,
                          const FieldSelection &field = {}, const ReadLimits &limits = {});

// A .vtu compressed with a compressor hoct's reader lacks (LZ4, LZMA): read_vtu and
// read_vtu_piece hand such a file to the external reader (io/external_reader.hpp) if one is
// registered, else throw this.
class VtuCompressorError : public InputError {
public:
  using InputError::InputError;
};

// vtkGhostType's bit of a point or cell that another piece owns (VTK's DUPLICATEPOINT and
// DUPLICATECELL).
constexpr uint8_t kDuplicateGhost = 1;

// The bookkeeping arrays of one piece of a partitioned output, which the collection readers
// (io/pvtu_reader.hpp, io/pvd_reader.hpp) need to join pieces and read_vtu to warn about a piece
// read alone. Each is empty when the file does not have it; else it has one entry per point or
// per cell of the MeshInput read with it (the skipped vertex and line cells have none).
struct VtuPieceArrays {
  std::vector<uint8_t> cell_ghost;  // CellData vtkGhostType
  std::vector<uint8_t> point_ghost; // PointData vtkGhostType
  std::vector<int64_t> global_ids;  // the point ids global to the pieces
  std::string global_ids_name;      // the array they were read from
  // The cells and points with kDuplicateGhost (copies of another piece's).
  int64_t ghost_cells = 0, ghost_points = 0;
};

struct VtuPieceRequest {
  // The point-data array of global ids: this one (a .pvtu's PPointData GlobalIds attribute),
  // else the one the piece's PointData GlobalIds attribute names, else an array "GlobalIds".
  std::string global_ids_name;
  // A file whose pieces are all empty (no points, no cells: an idle rank's) gives an empty
  // MeshInput instead of an error.
  bool allow_empty = false;
};

// read_vtu with the piece's bookkeeping arrays, for the collection readers: any --step / --time
// is theirs to apply (not refused), and no warning is added for ghost arrays.
MeshInput read_vtu_piece(const std::string &path, const FieldSelection &field,
                         const ReadLimits &limits, const VtuPieceRequest &request,
                         VtuPieceArrays &arrays);

} // namespace hoct
