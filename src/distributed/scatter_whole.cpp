#include "distributed/scatter_whole.hpp"

#include "mesh/mesh_fingerprint.hpp"
#include "mesh/mesh_partition.hpp"
#include "util/byte_codec.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hoct {
namespace {

constexpr int kShareTag = 1 << 21;
// Arrays travel in blocks of at most this many bytes (MPI counts are ints), formatted from the
// whole as they go: rank 0 holds one block of a share, never the share itself.
constexpr std::size_t kBlockBytes = std::size_t{8} << 20;

template <class T> std::size_t block_items() {
  return std::max<std::size_t>(1, kBlockBytes / sizeof(T));
}

// Sends the n items item(0), ..., item(n - 1) to `to`, block by block.
template <class T, class Item>
void send_items(std::size_t n, const Item &item, int to, MPI_Comm comm) {
  std::vector<T> block;
  block.reserve(std::min(n, block_items<T>()));
  for (std::size_t at = 0; at < n; at += block_items<T>()) {
    block.clear();
    for (std::size_t i = at; i < std::min(n, at + block_items<T>()); ++i)
      block.push_back(item(i));
    MPI_Send(block.data(), static_cast<int>(block.size() * sizeof(T)), MPI_BYTE, to, kShareTag,
             comm);
  }
}

// Receives n items sent by send_items into `out`.
template <class T, class V> void receive_items(std::size_t n, V &out, MPI_Comm comm) {
  out.resize(n);
  for (std::size_t at = 0; at < n; at += block_items<T>()) {
    const std::size_t k = std::min(n - at, block_items<T>());
    MPI_Recv(out.data() + at, static_cast<int>(k * sizeof(T)), MPI_BYTE, 0, kShareTag, comm,
             MPI_STATUS_IGNORE);
  }
}

// The sizes of a share's arrays and its scalars, sent first.
struct ShareHeader {
  uint64_t points = 0, cells = 0, nodes = 0;
  int64_t first_cell = 0, first_triangle = 0, whole_cells = 0, whole_points = 0;
  double coordinate_precision = 0, value_precision = 0;
  uint8_t cells_split = 0, has_kinds = 0;
};

// Rank r's share, formatted from the whole block by block as it is sent (the same arrays as
// extract_piece and piece_point_spans make). `local` (a slot per whole point, all -1) is the
// points' index in the share while it is sent, and all -1 again after.
void send_share(const MeshInput &whole, std::span<const std::array<int32_t, 2>> spans, int ranks,
                int r, std::vector<int64_t> &local, MPI_Comm comm) {
  const auto [begin, end] = piece_cell_range(static_cast<int64_t>(whole.num_cells()), ranks, r);
  const int64_t n0 = whole.cell_offsets[begin], n1 = whole.cell_offsets[end];
  std::vector<int64_t> g; // the share's points, ascending in the whole's order
  for (int64_t k = n0; k < n1; ++k)
    if (local[whole.cell_nodes[k]] < 0) {
      local[whole.cell_nodes[k]] = 0;
      g.push_back(whole.cell_nodes[k]);
    }
  std::sort(g.begin(), g.end());
  for (std::size_t i = 0; i < g.size(); ++i)
    local[g[i]] = static_cast<int64_t>(i);
  ShareHeader h;
  h.points = g.size();
  h.cells = static_cast<uint64_t>(end - begin);
  h.nodes = static_cast<uint64_t>(n1 - n0);
  h.first_cell = begin;
  h.first_triangle = triangles_before(whole, begin);
  h.whole_cells = static_cast<int64_t>(whole.num_cells());
  h.whole_points = static_cast<int64_t>(whole.num_points());
  h.coordinate_precision = whole.coordinate_precision;
  h.value_precision = whole.value_precision;
  h.cells_split = whole.lagrange_triangles_only() ? 0 : 1;
  h.has_kinds = whole.cell_kind.empty() ? 0 : 1;
  ByteWriter w;
  w.value(h);
  w.text(whole.field_name);
  w.text(whole.field_detail);
  w.text(whole.source);
  const uint64_t header_bytes = w.out.size();
  MPI_Send(&header_bytes, 1, MPI_UINT64_T, r, kShareTag, comm);
  MPI_Send(w.out.data(), static_cast<int>(w.out.size()), MPI_BYTE, r, kShareTag, comm);
  send_items<Vec3>(
      g.size(), [&](std::size_t i) { return whole.points[g[i]]; }, r, comm);
  send_items<double>(
      g.size(), [&](std::size_t i) { return whole.values[g[i]]; }, r, comm);
  send_items<int64_t>(
      h.cells + 1, [&](std::size_t c) { return whole.cell_offsets[begin + c] - n0; }, r, comm);
  send_items<int64_t>(
      h.nodes, [&](std::size_t k) { return local[whole.cell_nodes[n0 + k]]; }, r, comm);
  send_items<uint8_t>(
      h.cells, [&](std::size_t c) { return whole.cell_degree[begin + c]; }, r, comm);
  if (h.has_kinds)
    send_items<uint8_t>(
        h.cells, [&](std::size_t c) { return whole.cell_kind[begin + c]; }, r, comm);
  send_items<int64_t>(
      g.size(), [&](std::size_t i) { return g[i]; }, r, comm);
  send_items<std::array<int32_t, 2>>(
      g.size(), [&](std::size_t i) { return spans[g[i]]; }, r, comm);
  for (const int64_t q : g)
    local[q] = -1;
}

RankInput receive_share(MPI_Comm comm) {
  uint64_t header_bytes = 0;
  MPI_Recv(&header_bytes, 1, MPI_UINT64_T, 0, kShareTag, comm, MPI_STATUS_IGNORE);
  std::vector<std::byte> bytes(static_cast<std::size_t>(header_bytes));
  MPI_Recv(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, kShareTag, comm,
           MPI_STATUS_IGNORE);
  ByteReader reader(bytes, "a rank's share of the mesh");
  const ShareHeader h = reader.value<ShareHeader>();
  RankInput in;
  MeshInput &m = in.piece.input;
  m.field_name = reader.text();
  m.field_detail = reader.text();
  m.source = reader.text();
  m.coordinate_precision = h.coordinate_precision;
  m.value_precision = h.value_precision;
  receive_items<Vec3>(h.points, m.points, comm);
  receive_items<double>(h.points, m.values, comm);
  receive_items<int64_t>(h.cells + 1, m.cell_offsets, comm);
  receive_items<int64_t>(h.nodes, m.cell_nodes, comm);
  receive_items<uint8_t>(h.cells, m.cell_degree, comm);
  if (h.has_kinds)
    receive_items<uint8_t>(h.cells, m.cell_kind, comm);
  receive_items<int64_t>(h.points, in.piece.global_point, comm);
  receive_items<std::array<int32_t, 2>>(h.points, in.piece.point_span, comm);
  in.piece.first_cell = h.first_cell;
  in.first_triangle = h.first_triangle;
  in.whole_cells = h.whole_cells;
  in.whole_points = h.whole_points;
  in.cells_split = h.cells_split != 0;
  in.source = m.source;
  in.field_name = m.field_name;
  return in;
}

} // namespace

RankInput scatter_whole(const MeshInput *whole, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (rank != 0)
    return receive_share(comm);
  // The spans once (a pass over the whole's cells), then each share sent as it is formatted.
  const std::vector<std::array<int32_t, 2>> spans = point_piece_spans(*whole, ranks);
  if (ranks > 1) {
    std::vector<int64_t> local(whole->num_points(), -1);
    for (int r = 1; r < ranks; ++r)
      send_share(*whole, spans, ranks, r, local, comm);
  }
  RankInput own;
  const auto [begin, end] = piece_cell_range(static_cast<int64_t>(whole->num_cells()), ranks, 0);
  own.piece = extract_piece(*whole, begin, end);
  own.piece.point_span = piece_point_spans(own.piece.global_point, spans);
  own.first_triangle = triangles_before(*whole, begin);
  own.whole_cells = static_cast<int64_t>(whole->num_cells());
  own.whole_points = static_cast<int64_t>(whole->num_points());
  own.cells_split = !whole->lagrange_triangles_only();
  own.source = whole->source;
  own.field_name = whole->field_name;
  own.fingerprint = mesh_fingerprint(*whole);
  return own;
}

} // namespace hoct
