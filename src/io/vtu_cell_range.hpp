// One part of a .vtu file read alone, without the rest: a range of its cells and the points they
// use, for processes that each read their own share of one file (distributed/vtu_by_ranks). The
// points are read in blocks of consecutive ids: Lagrange meshes number their corner points apart
// from their edge and interior nodes, so that a range of cells uses points in a few runs of ids
// spread over the file, not one range. The file must be one piece whose arrays are raw appended
// data (what hoct, VTK and ParaView write by default, compressed or not): each array's range is
// read from the file at its offset, and a compressed array's blocks over the range alone are
// inflated.
#pragma once

#include "io/field_selection.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hoct {

struct VtuCellRange {
  // The file's cells [cell_begin, cell_end) that are surface cells (vertex and line cells
  // skipped, as read_vtu skips them), their nodes in hoct's order as the file's point ids; the
  // points and values of the blocks of `point_block` consecutive points that hold a point those
  // cells use or one of the points [check_begin, check_end), block after block.
  MeshInput input;
  int64_t cell_begin = 0, cell_end = 0;
  // Part `part` of `parts` of the file's points: checked here (finite coordinates and values),
  // so that the parts together check every point as read_vtu does.
  int64_t check_begin = 0, check_end = 0;
  int64_t file_points = 0, file_cells = 0; // the piece's NumberOfPoints and NumberOfCells
  // Per block of the file's points, where its first point is in input.points (-1: not read).
  int64_t point_block = 1;
  std::vector<int64_t> block_first;
  // False where the cells use points spread over so many blocks (points numbered at random) that
  // the part would read several times the points it uses: then only the checked share is read,
  // and the caller gets the cells' points from the parts that checked them.
  bool used_points_read = true;
  // The index in input.points of the file's point `id` (one of a block read).
  int64_t point_index(int64_t id) const {
    return block_first[static_cast<std::size_t>(id / point_block)] + id % point_block;
  }
};

// Part `part` of `parts` of the file's cells ([n part / parts, n (part + 1) / parts)) and of its
// points (the points the cells use, unless used_points_read says otherwise). Empty (with `why`) for
// a file that cannot be read by parts: not one piece of raw appended arrays, ghost arrays (a piece
// of a partitioned output), rational weights, or a file this process cannot open (the others' may
// be another path, as in mpirun's MPMD form). Throws InputError for what this part finds wrong in
// the file (read_vtu names the same problem, or one of a lower part first).
std::optional<VtuCellRange> read_vtu_cell_range(const std::string &path,
                                                const FieldSelection &field,
                                                const ReadLimits &limits, int part, int parts,
                                                std::string &why);

} // namespace hoct
