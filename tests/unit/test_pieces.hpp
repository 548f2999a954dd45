// Every piece of a mesh cut into `pieces` pieces of contiguous cells (mesh/mesh_partition), as an
// MPI rank holds its own: its mesh built with the whole's scales and its place in the whole,
// reduced by `piece_result` (piece_trees, reeb_piece) and passed through bytes as the ranks send
// them. Returns them in piece order, and the field's reference value in `reference`.
#pragma once

#include "exact/exact_tree_options.hpp"
#include "exact/piece_codec.hpp"
#include "exact/piece_trees.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_partition.hpp"

#include <vector>

namespace hoct::testing {

template <class PieceResult>
std::vector<PieceTrees> pieces_of(const MeshInput &whole, int pieces, const MeshScales &scales,
                                  bool augmented, double &reference, PieceResult piece_result) {
  const auto spans = point_piece_spans(whole, pieces);
  std::vector<PieceTrees> out;
  for (int r = 0; r < pieces; ++r) {
    const auto [begin, end] = piece_cell_range(static_cast<int64_t>(whole.num_cells()), pieces, r);
    const MeshPiece piece = extract_piece(whole, begin, end);
    MeshBuildOptions bo;
    bo.throw_on_error = false; // a piece may hold several fans around a shared point
    bo.whole_scales = [&](const MeshScales &) { return scales; };
    const Mesh mesh = build_mesh(piece.input, bo);
    reference = mesh.field.reference();
    const auto piece_spans = piece_point_spans(piece.global_point, spans);
    PiecePlace place{r, piece.global_point, begin, triangles_before(whole, begin), piece_spans};
    ExactTreeOptions eo;
    eo.augmented = augmented;
    eo.threads = 1;
    TreeTimings time;
    out.push_back(decode_piece_trees(encode_piece_trees(piece_result(mesh, place, eo, time))));
  }
  return out;
}

} // namespace hoct::testing
