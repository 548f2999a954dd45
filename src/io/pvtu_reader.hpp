// Reader for VTK XML parallel unstructured grids (.pvtu): the pieces it lists (.vtu files, one
// per rank of a partitioned solver or of VTK's parallel writer) read and joined into one mesh.
#pragma once

#include "io/field_selection.hpp"
#include "io/piece_join.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

// Reads every <Piece Source="..."/> (a .vtu file relative to the .pvtu's directory, never
// outside it) with the VTU reader and joins them (io/piece_join.hpp): ghost cells and points
// dropped by vtkGhostType, the shared points merged by the global ids the PPointData's GlobalIds
// attribute names (else an array "GlobalIds") or, without ids in every piece, by position.
// The memory budget covers all pieces together. Errors name the .pvtu, the piece and its file.
// `field` must be of the default step: a .pvtu holds one.
MeshInput read_pvtu(const std::string &path, const FieldSelection &field = {},
                    const ReadLimits &limits = {});

// What a .pvtu lists: its piece files (checked as read_pvtu checks them) and the name of the
// global ids array its PPointData declares (empty if none).
struct PvtuListing {
  std::string path;
  std::vector<std::string> files;
  std::string ids_name;
};
PvtuListing list_pvtu(const std::string &path, const FieldSelection &field = {});

// Piece k of a listing, as read_pvtu reads it (its ghost and id arrays kept); `budget` counts
// the pieces read before it. Errors name the .pvtu, the piece and its file.
FilePiece read_pvtu_piece(const PvtuListing &listing, std::size_t k, const FieldSelection &field,
                          const ReadLimits &budget);

// The .pvtu in the directory of `vtu_path` that lists it as a piece (its path as vtu_path's
// directory is written), or "" if there is none (or the directory holds too many to look).
std::string find_listing_pvtu(const std::string &vtu_path);

// The warning for a .vtu that holds one piece of a partitioned output, read alone: it has
// `ghost_cells` ghost cells and `ghost_points` ghost points (vtkGhostType), which it keeps.
std::string lone_piece_warning(const std::string &vtu_path, int64_t ghost_cells,
                               int64_t ghost_points);

} // namespace hoct
