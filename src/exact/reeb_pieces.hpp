// The Reeb graph of a partitioned mesh that is not a disk or a sphere (holes, handles, a twist,
// several components), computed piece by piece (docs/ALGORITHM.md §7, §9).
//
// The join/split merge of exact/piece_trees is exact only where the level sets make no loops.
// Here the surface is cut into disks along the pieces' borders and, inside each piece, along its
// own cut graph (mesh/cut_surface; a point where the piece holds two or more fans is cut apart
// too). Each piece reduces its disks' join and split trees to the nodes the gluing needs: the
// copies of its cut points and the nodes along its cut edges and along the edges it shares with
// other pieces. The pieces' disks' contour trees are glued back along all those seams in a tree
// of groups of pieces (exact/reeb_group): the whole surface's Reeb graph, the one a single
// process computes from its own cut, with the same nodes, values, places and arcs for any number
// of pieces.
#pragma once

#include "exact/exact_tree_options.hpp"
#include "exact/piece_trees.hpp"
#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <cstdint>

namespace hoct {

// One piece's kept join and split trees of its disks, and the chains of its cut edges and of
// the edges it shares with other pieces (PieceTrees::chains: each edge's ends and edge nodes,
// one chain per copy; a point's copies are kept nodes with one key). Counts count each of the
// piece's own copies once.
// With `arcs`, also the piece's graph with geometry there (its cut's copies of a point linked),
// to draw the whole graph's arcs (exact/piece_arcs).
PieceTrees reeb_piece(const Mesh &piece, const PiecePlace &place, const ExactTreeOptions &options,
                      TreeTimings &time, PieceArcGraph *arcs = nullptr);

} // namespace hoct
