#include "distributed/pieces_gather.hpp"

#include "distributed/mpi_exchange.hpp"
#include "util/byte_codec.hpp"

#include <string>
#include <utility>

namespace hoct {

namespace {

// A piece as it travels to rank 0: what join_pieces reads of it.
void encode_piece(ByteWriter &w, const FilePiece &p) {
  const MeshInput &m = p.input;
  w.array(m.points);
  w.array(m.values);
  w.array(m.cell_offsets);
  w.array(m.cell_nodes);
  w.array(m.cell_degree);
  w.array(m.cell_kind);
  w.value(m.coordinate_precision);
  w.value(m.value_precision);
  w.text(m.field_name);
  w.text(m.source);
  w.array(p.arrays.cell_ghost);
  w.array(p.arrays.point_ghost);
  w.array(p.arrays.global_ids);
  w.text(p.arrays.global_ids_name);
  w.value(p.arrays.ghost_cells);
  w.value(p.arrays.ghost_points);
  w.text(p.file);
}

FilePiece decode_piece(ByteReader &r) {
  FilePiece p;
  MeshInput &m = p.input;
  m.points = r.array<Vec3, PooledAllocator<Vec3>>();
  m.values = r.array<double, PooledAllocator<double>>();
  m.cell_offsets = r.array<int64_t, PooledAllocator<int64_t>>();
  m.cell_nodes = r.array<int64_t, PooledAllocator<int64_t>>();
  m.cell_degree = r.array<uint8_t, PooledAllocator<uint8_t>>();
  m.cell_kind = r.array<uint8_t, PooledAllocator<uint8_t>>();
  m.coordinate_precision = r.value<double>();
  m.value_precision = r.value<double>();
  m.field_name = r.text();
  m.source = r.text();
  p.arrays.cell_ghost = r.array<uint8_t>();
  p.arrays.point_ghost = r.array<uint8_t>();
  p.arrays.global_ids = r.array<int64_t>();
  p.arrays.global_ids_name = r.text();
  p.arrays.ghost_cells = r.value<int64_t>();
  p.arrays.ghost_points = r.value<int64_t>();
  p.file = r.text();
  return p;
}

std::vector<std::byte> encode_pieces(const std::vector<FilePiece> &pieces) {
  ByteWriter w;
  w.value<uint64_t>(pieces.size());
  for (const FilePiece &p : pieces)
    encode_piece(w, p);
  return std::move(w.out);
}

MeshInput join_gathered(std::vector<std::vector<std::byte>> all, const std::string &where,
                        int threads) {
  std::vector<FilePiece> joined;
  for (std::size_t r = 0; r < all.size(); ++r) {
    ByteReader in(all[r], "the pieces of rank " + std::to_string(r));
    for (uint64_t k = in.value<uint64_t>(); k > 0; --k)
      joined.push_back(decode_piece(in));
    std::vector<std::byte>().swap(all[r]);
  }
  return join_pieces(std::move(joined), where, /*by_ids=*/true, threads);
}

} // namespace

MeshInput join_pieces_on_root(const std::vector<FilePiece> &pieces, const std::string &where,
                              int threads, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::vector<std::vector<std::byte>> all = gather_bytes(comm, encode_pieces(pieces));
  return rank == 0 ? join_gathered(std::move(all), where, threads) : MeshInput{};
}

MeshInput join_pieces_everywhere(const std::vector<FilePiece> &pieces, const std::string &where,
                                 int threads, MPI_Comm comm) {
  return join_gathered(all_gather_bytes(comm, encode_pieces(pieces)), where, threads);
}

} // namespace hoct
