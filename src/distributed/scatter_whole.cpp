#include "distributed/scatter_whole.hpp"

#include "mesh/mesh_fingerprint.hpp"
#include "mesh/mesh_partition.hpp"
#include "util/byte_codec.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace hoct {
namespace {

void put_text(ByteWriter &w, const std::string &s) {
  w.array(std::vector<char>(s.begin(), s.end()));
}

std::string take_text(ByteReader &r) {
  const std::vector<char> v = r.array<char>();
  return std::string(v.begin(), v.end());
}

// A share as it travels: its piece (cells, points, values, the points' whole ids and spans) and
// the whole's counts. The fingerprint stays on rank 0.
std::vector<std::byte> encode_share(const RankInput &in) {
  ByteWriter w;
  const MeshInput &m = in.piece.input;
  w.array(m.points);
  w.array(m.values);
  w.array(m.cell_offsets);
  w.array(m.cell_nodes);
  w.array(m.cell_degree);
  w.array(m.cell_kind);
  w.value(m.coordinate_precision);
  w.value(m.value_precision);
  put_text(w, m.field_name);
  put_text(w, m.field_detail);
  put_text(w, m.source);
  w.array(in.piece.global_point);
  w.value(in.piece.first_cell);
  w.array(in.piece.point_span);
  w.value(in.first_triangle);
  w.value(in.whole_cells);
  w.value(in.whole_points);
  w.value<uint8_t>(in.cells_split ? 1 : 0);
  put_text(w, in.source);
  put_text(w, in.field_name);
  return std::move(w.out);
}

RankInput decode_share(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "a rank's share of the mesh");
  RankInput in;
  MeshInput &m = in.piece.input;
  m.points = r.array<Vec3, PooledAllocator<Vec3>>();
  m.values = r.array<double, PooledAllocator<double>>();
  m.cell_offsets = r.array<int64_t, PooledAllocator<int64_t>>();
  m.cell_nodes = r.array<int64_t, PooledAllocator<int64_t>>();
  m.cell_degree = r.array<uint8_t, PooledAllocator<uint8_t>>();
  m.cell_kind = r.array<uint8_t, PooledAllocator<uint8_t>>();
  m.coordinate_precision = r.value<double>();
  m.value_precision = r.value<double>();
  m.field_name = take_text(r);
  m.field_detail = take_text(r);
  m.source = take_text(r);
  in.piece.global_point = r.array<int64_t>();
  in.piece.first_cell = r.value<int64_t>();
  in.piece.point_span = r.array<std::array<int32_t, 2>>();
  in.first_triangle = r.value<int64_t>();
  in.whole_cells = r.value<int64_t>();
  in.whole_points = r.value<int64_t>();
  in.cells_split = r.value<uint8_t>() != 0;
  in.source = take_text(r);
  in.field_name = take_text(r);
  return in;
}

constexpr int kShareTag = 1 << 21;
constexpr std::size_t kMessageBytes = std::size_t{1} << 30;

void send_bytes(const std::vector<std::byte> &bytes, int to, MPI_Comm comm) {
  const uint64_t n = bytes.size();
  MPI_Send(&n, 1, MPI_UINT64_T, to, kShareTag, comm);
  for (std::size_t at = 0; at < bytes.size(); at += kMessageBytes)
    MPI_Send(bytes.data() + at, static_cast<int>(std::min(kMessageBytes, bytes.size() - at)),
             MPI_BYTE, to, kShareTag, comm);
}

std::vector<std::byte> receive_bytes(MPI_Comm comm) {
  uint64_t n = 0;
  MPI_Recv(&n, 1, MPI_UINT64_T, 0, kShareTag, comm, MPI_STATUS_IGNORE);
  std::vector<std::byte> bytes(static_cast<std::size_t>(n));
  for (std::size_t at = 0; at < bytes.size(); at += kMessageBytes)
    MPI_Recv(bytes.data() + at, static_cast<int>(std::min(kMessageBytes, bytes.size() - at)),
             MPI_BYTE, 0, kShareTag, comm, MPI_STATUS_IGNORE);
  return bytes;
}

// Rank r's share of the whole, as distributed_tree(whole, ...) makes it on rank r.
RankInput share_of(const MeshInput &whole, std::span<const std::array<int32_t, 2>> spans, int ranks,
                   int r) {
  RankInput in;
  const auto [begin, end] = piece_cell_range(static_cast<int64_t>(whole.num_cells()), ranks, r);
  in.piece = extract_piece(whole, begin, end);
  in.piece.point_span = piece_point_spans(in.piece.global_point, spans);
  in.first_triangle = triangles_before(whole, begin);
  in.whole_cells = static_cast<int64_t>(whole.num_cells());
  in.whole_points = static_cast<int64_t>(whole.num_points());
  in.cells_split = !whole.lagrange_triangles_only();
  in.source = whole.source;
  in.field_name = whole.field_name;
  return in;
}

} // namespace

RankInput scatter_whole(const MeshInput *whole, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (rank != 0)
    return decode_share(receive_bytes(comm));
  // The spans once (a pass over the whole's cells), then each share cut, sent and freed.
  const std::vector<std::array<int32_t, 2>> spans = point_piece_spans(*whole, ranks);
  for (int r = 1; r < ranks; ++r)
    send_bytes(encode_share(share_of(*whole, spans, ranks, r)), r, comm);
  RankInput own = share_of(*whole, spans, ranks, 0);
  own.fingerprint = mesh_fingerprint(*whole);
  return own;
}

} // namespace hoct
