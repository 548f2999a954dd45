// The piecewise-linear methods' trees of a mesh partitioned into pieces, as the exact tree's
// (exact/piece_trees): each piece makes the PL mesh of its own cells and keeps of its join and
// split trees the critical vertices and the vertices other pieces hold too; merge_piece_trees
// joins the pieces' kept trees.
// - linear: the cells split through their Lagrange nodes (pl/pl_mesh). A vertex is named by its
//   point in the whole (NodeKey::Vertex) and placed in the first input cell that has it, as
//   split_lagrange_cells places it.
// - refine: every triangle cut into K x K sub-triangles of the exact field (pl/refinement). Its
//   vertices are named as the whole's refinement numbers them: mesh vertices by their point, the
//   lattice points on an edge by the edge's points and their step from its lower point
//   (NodeKey::EdgeNode), the others by their triangle in the whole and their rank in it
//   (NodeKey::Interior); each is placed where the whole's refinement places it (a vertex in its
//   lowest triangle, an edge point in its edge's lowest triangle: the lowest wins).
// Equal values are ordered by the key, as the whole's PL sweep orders them by vertex id: the tree
// is the whole's for any number of pieces.
#pragma once

#include "exact/piece_trees.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_input.hpp"
#include "pl/pl_mesh.hpp"
#include "tree/scalar_graph.hpp"
#include "tree/tree_result.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hoct {

struct PlPieceTrees {
  PieceTrees trees;
  // The piece's PL triangles, its points no lower piece uses (their span starts at it), and
  // (refine) its triangles' own points: summed over the pieces, the whole's, with the whole's
  // edges' lattice points (K - 1 per edge) the whole's PL vertices.
  int64_t triangles = 0, own_points = 0, cell_points = 0;
};

// A piece's PL mesh with its vertices named, spanned and placed as the whole's PL mesh does it:
// `key` and `span` per point of `pl`, `point` the sweeps' vertices (linear: the points the cells
// use; empty: every point of pl, `local` then empty too; else local[p] is point p's index in it).
struct PlPieceMesh {
  PlMesh pl;
  std::vector<int64_t> point, local;
  std::vector<NodeKey> key;
  std::vector<std::array<int32_t, 2>> span;
  std::vector<int64_t> triangle; // refine: the piece's triangle that places the point
  const Mesh *refined = nullptr; // refine: the piece's mesh (its cells' origins)
  int64_t own_points = 0, cell_points = 0;
};
PlPieceMesh linear_piece_mesh(const MeshInput &piece, const PiecePlace &place);
PlPieceMesh refined_piece_mesh(const Mesh &mesh, const PiecePlace &place, int k);
// The piece's PL graph to draw the whole tree's arcs through (exact/piece_arcs): its
// 1-skeleton, with the kept nodes of `trees` at points `points` of pl (a cut piece's copies of
// one point joined).
void pl_arc_graph(const PlPieceMesh &m, const PiecePlace &place, const PieceTrees &trees,
                  std::vector<int64_t> points, PieceArcGraph &arcs);

// Point p of the piece's PL mesh as a kept node (its value left to the caller).
PieceNode pl_piece_node(const PlPieceMesh &m, const PiecePlace &place, int64_t p);
// The kept join and split trees (sweep_merge_trees) of vertices 0..n-1 over points of the
// piece's PL mesh (`point[i]`: vertex i's; empty: vertex i is point i), with the values, edges,
// flags of vertices kept whatever they are and ascending order given, as pl_piece_node's;
// `kept` (optional): the kept vertices, in the nodes' order.
PieceTrees pl_kept_trees(const PlPieceMesh &m, const PiecePlace &place,
                         std::span<const double> values, std::span<const GraphEdge> edges,
                         std::span<const uint8_t> keep, std::span<const int64_t> order,
                         std::span<const int64_t> point, int threads,
                         std::vector<int64_t> *kept = nullptr);

// One piece's kept trees by the linear method (`augmented`: every vertex kept). Its cells must
// be Lagrange triangles and quadrilaterals (nodal_lagrange_cells: the split makes no points of
// its own). With `arcs`, the piece's PL graph there, to draw the whole tree's arcs
// (exact/piece_arcs).
PlPieceTrees pl_piece_trees(const MeshInput &piece, const PiecePlace &place, bool augmented,
                            int threads = 1, PieceArcGraph *arcs = nullptr);

// One piece's kept trees by the refine method (`mesh`: the piece's, built with the whole's
// scales), K = `k` sub-triangles per triangle edge; `arcs` as above.
PlPieceTrees refined_piece_trees(const Mesh &mesh, const PiecePlace &place, int k, bool augmented,
                                 int threads = 1, PieceArcGraph *arcs = nullptr);

// The whole's PL mesh's counts from the sums of its pieces' counts (`k`: the refine method's K;
// 0 for the linear method) and the whole surface's Euler characteristic (refine: its edges
// E = V + T - chi carry K - 1 lattice points each).
PlCounts whole_pl_counts(int64_t triangles, int64_t own_points, int64_t cell_points, int k,
                         int64_t euler_characteristic);

// The PL tree of the whole from the group of all its pieces (`method`: "linear" or "refine
// k=K"), with the whole's PL mesh's counts; `reference` is added back to the values.
TreeResult pl_tree_of_pieces(const PieceTrees &all, bool augmented, const std::string &method,
                             const PlCounts &counts, double reference);

// A tree or graph of pieces made the PL method's result: its name and the PL mesh's counts.
void mark_pl_result(TreeResult &r, const std::string &method, const PlCounts &counts);

} // namespace hoct
