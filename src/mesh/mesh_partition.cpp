#include "mesh/mesh_partition.hpp"

#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <stdexcept>

namespace hoct {

std::array<int64_t, 2> piece_cell_range(int64_t cells, int pieces, int piece) {
  if (pieces < 1 || piece < 0 || piece >= pieces)
    throw std::invalid_argument("piece_cell_range: no piece " + std::to_string(piece) + " of " +
                                std::to_string(pieces));
  auto at = [&](int64_t r) {
    return static_cast<int64_t>((static_cast<__int128>(cells) * r) / pieces);
  };
  return {at(piece), at(piece + 1)};
}

namespace {

MeshPiece extract(const MeshInput &whole, int64_t begin, int64_t end, int pieces, int piece) {
  MeshPiece p;
  MeshInput &in = p.input;
  in.field_name = whole.field_name;
  in.source = whole.source;
  in.field_detail = whole.field_detail;
  in.coordinate_precision = whole.coordinate_precision;
  in.value_precision = whole.value_precision;
  p.first_cell = begin;
  const int64_t n0 = whole.cell_offsets[begin], n1 = whole.cell_offsets[end];
  // The points the cells use, numbered in ascending order of the whole's indices: a scan over
  // the whole's points for a large piece, a sort of the cells' nodes for a small one (a piece of
  // many ranks' mesh must not cost as much as the whole).
  std::vector<int64_t> &g = p.global_point;
  const int64_t np = static_cast<int64_t>(whole.num_points());
  // Pooled: pages the reading freed serve here.
  UninitializedVector<int64_t> local;
  if (4 * (n1 - n0) < np) {
    g.assign(whole.cell_nodes.begin() + n0, whole.cell_nodes.begin() + n1);
    std::sort(g.begin(), g.end());
    g.erase(std::unique(g.begin(), g.end()), g.end());
  } else {
    local.resize(static_cast<std::size_t>(np));
    std::fill(local.begin(), local.end(), int64_t{-1});
    for (int64_t k = n0; k < n1; ++k)
      local[whole.cell_nodes[k]] = 0;
    int64_t n = 0;
    for (int64_t q = 0; q < np; ++q)
      n += local[q] == 0;
    g.reserve(static_cast<std::size_t>(n));
    for (int64_t q = 0; q < np; ++q)
      if (local[q] == 0) {
        local[q] = static_cast<int64_t>(g.size());
        g.push_back(q);
      }
  }
  // Each cell node's index in the piece.
  const auto local_index = [&](int64_t q) {
    if (!local.empty())
      return local[q];
    return static_cast<int64_t>(std::lower_bound(g.begin(), g.end(), q) - g.begin());
  };
  in.points.resize(g.size());
  in.values.resize(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    in.points[i] = whole.points[g[i]];
    in.values[i] = whole.values[g[i]];
  }
  in.cell_offsets.resize(static_cast<std::size_t>(end - begin) + 1);
  in.cell_nodes.resize(static_cast<std::size_t>(n1 - n0));
  in.cell_degree.assign(whole.cell_degree.begin() + begin, whole.cell_degree.begin() + end);
  if (!whole.cell_kind.empty())
    in.cell_kind.assign(whole.cell_kind.begin() + begin, whole.cell_kind.begin() + end);
  for (int64_t c = begin; c <= end; ++c)
    in.cell_offsets[c - begin] = whole.cell_offsets[c] - n0;
  for (int64_t k = n0; k < n1; ++k)
    in.cell_nodes[k - n0] = local_index(whole.cell_nodes[k]);
  if (pieces == 0)
    return p;
  // The spans: the other pieces' cells' nodes that are the piece's points (a bit per whole
  // point rejects the others before any lookup).
  p.point_span.assign(g.size(), {piece, piece});
  UninitializedVector<uint64_t> mine(static_cast<std::size_t>(np + 63) / 64);
  std::fill(mine.begin(), mine.end(), uint64_t{0});
  for (const int64_t q : g)
    mine[static_cast<std::size_t>(q) >> 6] |= uint64_t{1} << (q & 63);
  const int64_t cells = static_cast<int64_t>(whole.num_cells());
  for (int r = 0; r < pieces; ++r) {
    if (r == piece)
      continue;
    const auto [b, e] = piece_cell_range(cells, pieces, r);
    for (int64_t k = whole.cell_offsets[b]; k < whole.cell_offsets[e]; ++k) {
      const int64_t q = whole.cell_nodes[k];
      if (!(mine[static_cast<std::size_t>(q) >> 6] >> (q & 63) & 1))
        continue;
      auto &s = p.point_span[static_cast<std::size_t>(local_index(q))];
      s[0] = std::min(s[0], static_cast<int32_t>(r));
      s[1] = std::max(s[1], static_cast<int32_t>(r));
    }
  }
  return p;
}

} // namespace

MeshPiece extract_piece(const MeshInput &whole, int64_t begin, int64_t end) {
  return extract(whole, begin, end, 0, 0);
}

MeshPiece partition_piece(const MeshInput &whole, int pieces, int piece) {
  const auto [begin, end] =
      piece_cell_range(static_cast<int64_t>(whole.num_cells()), pieces, piece);
  return extract(whole, begin, end, pieces, piece);
}

std::vector<std::array<int32_t, 2>> point_piece_spans(const MeshInput &whole, int pieces) {
  std::vector<std::array<int32_t, 2>> span(whole.num_points(), {-1, -1});
  const int64_t cells = static_cast<int64_t>(whole.num_cells());
  for (int r = 0; r < pieces; ++r) {
    const auto [begin, end] = piece_cell_range(cells, pieces, r);
    for (int64_t k = whole.cell_offsets[begin]; k < whole.cell_offsets[end]; ++k) {
      std::array<int32_t, 2> &s = span[whole.cell_nodes[k]];
      if (s[0] < 0)
        s[0] = r;
      s[1] = r;
    }
  }
  return span;
}

int64_t triangles_before(const MeshInput &whole, int64_t end) {
  if (whole.cell_kind.empty())
    return end;
  int64_t n = 0;
  for (int64_t c = 0; c < end; ++c)
    n += is_quadrilateral(whole.kind(static_cast<std::size_t>(c))) ? 2 : 1;
  return n;
}

std::vector<std::array<int32_t, 2>>
piece_point_spans(std::span<const int64_t> global_point,
                  std::span<const std::array<int32_t, 2>> whole_spans) {
  std::vector<std::array<int32_t, 2>> out(global_point.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = whole_spans[static_cast<std::size_t>(global_point[i])];
  return out;
}

} // namespace hoct
