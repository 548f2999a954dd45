// The piecewise-linear methods' Reeb graph of a partitioned mesh (docs/ALGORITHM.md §8), as the
// exact one (exact/reeb_pieces, exact/reeb_group): each piece's PL mesh (linear_piece_mesh,
// refined_piece_mesh) cut into disks along its own cut graph and apart at the points it shares,
// its disks' kept trees over the vertices the gluing needs (the cut points' copies, the ends of
// its cut edges' copies and of its PL edges other pieces hold), and the sides of those edges, one
// PL edge each (monotone: a segment); the groups glue them in the tree of ranks. A vertex keeps
// the whole's name (key), so ties fall as the whole's PL sweep orders them.
#pragma once

#include "exact/pl_piece_trees.hpp"
#include "exact/reeb_group.hpp"

namespace hoct {

// The piece's group (`augmented`: every vertex kept). With `arcs`, the piece's PL graph there
// (its uncut 1-skeleton; the kept copies of one point joined), to draw the whole graph's arcs
// (exact/piece_arcs).
ReebGroup pl_reeb_group(const PlPieceMesh &mesh, const PiecePlace &place, bool augmented,
                        int threads = 1, PieceArcGraph *arcs = nullptr);

// The PL Reeb graph of the whole from the group of all its pieces (`method`: "linear" or
// "refine k=K"), with the whole's PL mesh's counts; `reference` is added back to the values.
TreeResult pl_reeb_graph_of_group(const ReebGroup &all, bool augmented, const std::string &method,
                                  const PlCounts &counts, double reference);

} // namespace hoct
