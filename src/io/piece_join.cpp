#include "io/piece_join.hpp"

#include "mesh/duplicate_points.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace hoct {

namespace {

// Tolerance of merging, relative to the bounding-box diagonal (positions) and the largest
// magnitude of the values (values): as --merge-duplicates' default.
constexpr double kRelativeTolerance = 1e-9;

std::string position(const Vec3 &p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return s.str();
}

} // namespace

PieceParts concatenate_pieces(std::vector<FilePiece> &pieces, const std::string &where,
                              bool by_ids) {
  auto fail = [&](const std::string &what) { throw InputError(where + ": " + what); };
  PieceParts parts;
  MeshInput &out = parts.mesh;
  out.source = where;
  out.cell_offsets.assign(1, 0);
  std::string field_file;
  bool &ids = parts.ids;
  ids = by_ids;
  std::size_t &filled = parts.filled; // pieces that are not empty
  for (const FilePiece &p : pieces) {
    if (p.input.num_cells() == 0 && p.input.points.empty())
      continue;
    ++filled;
    ids = ids && !p.arrays.global_ids.empty();
    if (field_file.empty()) {
      out.field_name = p.input.field_name;
      field_file = p.file;
    } else if (p.input.field_name != out.field_name) {
      fail(p.file + ": field '" + p.input.field_name + "' differs from " + field_file + "'s '" +
           out.field_name + "' (name the field with --scalar)");
    }
  }
  // The kept cells and points, piece after piece.
  std::vector<uint32_t> &piece_of = parts.piece_of; // each point's piece
  std::vector<int64_t> &global = parts.global;      // each point's global id (when merging by ids)
  // Several pieces: the arrays reserved once for all of them (ghosts included: a bound), as
  // arrays reserved piece by piece to the size they reach would be copied again for each piece.
  if (filled > 1) {
    std::size_t points = 0, nodes = 0, cells = 0;
    for (const FilePiece &p : pieces) {
      points += p.input.points.size();
      nodes += p.input.cell_nodes.size();
      cells += p.input.num_cells();
    }
    out.points.reserve(points);
    out.values.reserve(points);
    out.cell_nodes.reserve(nodes);
    out.cell_offsets.reserve(cells + 1);
    out.cell_degree.reserve(cells);
    piece_of.reserve(points);
    if (ids)
      global.reserve(points);
  }
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    MeshInput &in = pieces[k].input;
    const VtuPieceArrays &a = pieces[k].arrays;
    const std::size_t np = in.points.size(), nc = in.num_cells();
    if (np == 0 && nc == 0)
      continue;
    if ((!a.cell_ghost.empty() && a.cell_ghost.size() != nc) ||
        (!a.point_ghost.empty() && a.point_ghost.size() != np) ||
        (ids && a.global_ids.size() != np))
      fail(pieces[k].file + ": ghost or id arrays do not match its points and cells");
    out.coordinate_precision = std::max(out.coordinate_precision, in.coordinate_precision);
    out.value_precision = std::max(out.value_precision, in.value_precision);
    auto ghost_flag = [](uint8_t g) { return (g & kDuplicateGhost) != 0; };
    if (std::none_of(a.cell_ghost.begin(), a.cell_ghost.end(), ghost_flag) &&
        std::none_of(a.point_ghost.begin(), a.point_ghost.end(), ghost_flag)) {
      // No ghosts: every point and cell kept, in order (the arrays moved or appended whole).
      const int64_t base = static_cast<int64_t>(out.points.size());
      piece_of.insert(piece_of.end(), np, static_cast<uint32_t>(k));
      if (ids)
        global.insert(global.end(), a.global_ids.begin(), a.global_ids.end());
      const bool kinds = !in.lagrange_triangles_only() || !out.cell_kind.empty();
      if (filled == 1) { // the only piece: its arrays are the mesh's
        out.points = std::move(in.points);
        out.values = std::move(in.values);
        out.cell_nodes = std::move(in.cell_nodes);
        out.cell_offsets = std::move(in.cell_offsets);
        out.cell_degree = std::move(in.cell_degree);
        out.cell_kind = std::move(in.cell_kind);
      } else {
        const int64_t node_base = static_cast<int64_t>(out.cell_nodes.size());
        const std::size_t first_cell = out.num_cells();
        out.points.insert(out.points.end(), in.points.begin(), in.points.end());
        out.values.insert(out.values.end(), in.values.begin(), in.values.end());
        for (const int64_t q : in.cell_nodes)
          out.cell_nodes.push_back(q + base);
        for (std::size_t c = 1; c <= nc; ++c)
          out.cell_offsets.push_back(in.cell_offsets[c] + node_base);
        out.cell_degree.insert(out.cell_degree.end(), in.cell_degree.begin(), in.cell_degree.end());
        if (kinds)
          for (std::size_t c = 0; c < nc; ++c)
            out.set_kind(first_cell + c, in.kind(c));
      }
      in = MeshInput();
      continue;
    }
    // Bit 1: used by a kept cell, bit 2: by a ghost cell.
    std::vector<uint8_t> use(np, 0);
    for (std::size_t c = 0; c < nc; ++c) {
      const uint8_t bit = !a.cell_ghost.empty() && (a.cell_ghost[c] & kDuplicateGhost) ? 2 : 1;
      for (int64_t i = in.cell_offsets[c]; i < in.cell_offsets[c + 1]; ++i)
        use[static_cast<std::size_t>(in.cell_nodes[i])] |= bit;
    }
    const int64_t base = static_cast<int64_t>(out.points.size());
    std::vector<int64_t> renumber(np, -1);
    int64_t next = base;
    for (std::size_t i = 0; i < np; ++i) {
      const bool ghost = !a.point_ghost.empty() && (a.point_ghost[i] & kDuplicateGhost);
      if (!(use[i] & 1) && (ghost || (use[i] & 2)))
        continue;
      renumber[i] = next++;
      out.points.push_back(in.points[i]);
      out.values.push_back(in.values[i]);
      piece_of.push_back(static_cast<uint32_t>(k));
      if (ids)
        global.push_back(a.global_ids[i]);
    }
    for (std::size_t c = 0; c < nc; ++c) {
      if (!a.cell_ghost.empty() && (a.cell_ghost[c] & kDuplicateGhost))
        continue;
      for (int64_t i = in.cell_offsets[c]; i < in.cell_offsets[c + 1]; ++i)
        out.cell_nodes.push_back(renumber[static_cast<std::size_t>(in.cell_nodes[i])]);
      out.cell_offsets.push_back(static_cast<int64_t>(out.cell_nodes.size()));
      out.cell_degree.push_back(in.cell_degree[c]);
      out.set_kind(out.cell_degree.size() - 1, in.kind(c));
    }
    in = MeshInput(); // released before the next piece is appended
  }
  return parts;
}

MeshInput join_pieces(std::vector<FilePiece> pieces, const std::string &where, bool by_ids,
                      int threads) {
  auto fail = [&](const std::string &what) { throw InputError(where + ": " + what); };
  PieceParts parts = concatenate_pieces(pieces, where, by_ids);
  if (parts.filled == 0)
    fail("every piece is empty (no points, no cells)");
  MeshInput &out = parts.mesh;
  const bool ids = parts.ids;
  const std::size_t filled = parts.filled;
  const std::vector<uint32_t> &piece_of = parts.piece_of;
  const std::vector<int64_t> &global = parts.global;
  if (out.num_cells() == 0)
    fail("no cells but ghost cells in any piece");
  // Each point's representative: itself, or the first point of another piece it is merged with.
  const std::size_t n = out.points.size();
  std::vector<int64_t> rep(n);
  const double diagonal = bounding_box_diagonal(out.points, threads);
  // Ids join exactly: positions agree within the coordinates' own rounding too.
  const double position_tolerance =
      diagonal * std::max(kRelativeTolerance, 4 * out.coordinate_precision);
  if (filled == 1) { // nothing to merge with
    for (std::size_t i = 0; i < n; ++i)
      rep[i] = static_cast<int64_t>(i);
  } else if (ids) {
    std::unordered_map<int64_t, int64_t> first;
    first.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto [it, fresh] = first.emplace(global[i], static_cast<int64_t>(i));
      rep[i] = it->second;
      if (fresh)
        continue;
      const Vec3 &p = out.points[i], &q = out.points[it->second];
      const double d = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      if (!(d <= position_tolerance))
        fail(pieces[piece_of[i]].file + " and " + pieces[piece_of[it->second]].file +
             ": the points of global id " + std::to_string(global[i]) + " are at " + position(q) +
             " and " + position(p) +
             ": the ids are not the same points'; they cannot join the pieces");
    }
  } else {
    std::vector<int64_t> all(n);
    for (std::size_t i = 0; i < n; ++i)
      all[i] = static_cast<int64_t>(i);
    const std::vector<int64_t> group =
        coincident_points(out.points, all, kRelativeTolerance * diagonal, threads);
    for (std::size_t i = 0; i < n; ++i)
      rep[i] = piece_of[static_cast<std::size_t>(group[i])] != piece_of[i]
                   ? group[i]
                   : static_cast<int64_t>(i);
  }
  double scale = 0;
  for (const double v : out.values)
    scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < n; ++i) {
    const int64_t r = rep[i];
    if (r == static_cast<int64_t>(i))
      continue;
    const double a = out.values[r], b = out.values[i];
    if (!(std::abs(a - b) <= kRelativeTolerance * scale)) {
      std::ostringstream m;
      m.precision(17);
      m << "the point at " << position(out.points[i]) << " has the value " << a << " in "
        << pieces[piece_of[r]].file << " and " << b << " in " << pieces[piece_of[i]].file << " of '"
        << out.field_name
        << "': the pieces disagree on the field there (a discontinuous field cannot be joined)";
      fail(m.str());
    }
  }
  // The merged points removed: the others keep their order.
  std::vector<int64_t> index(n);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (rep[i] != static_cast<int64_t>(i)) {
      index[i] = index[static_cast<std::size_t>(rep[i])];
      continue;
    }
    index[i] = static_cast<int64_t>(kept);
    out.points[kept] = out.points[i];
    out.values[kept] = out.values[i];
    ++kept;
  }
  out.points.resize(kept);
  out.values.resize(kept);
  for (int64_t &id : out.cell_nodes)
    id = index[static_cast<std::size_t>(id)];
  return std::move(out);
}

} // namespace hoct
