// A Reeb graph reduced in a tree of ranks (docs/ALGORITHM.md §8): a group of consecutive pieces
// keeps its part of the gluing done, and only what the groups beyond it still need.
//
// Each piece's disks have a contour forest (exact/reeb_pieces keeps the nodes the gluing needs).
// The Reeb graph of the whole is that forest with every seam glued back (tree/path_gluing): a
// point's nodes (one key) are one, the two sides of an edge held twice are one curve, segment by
// segment, each side along its path in its piece's disks. A group glues all it holds: its
// graph may have loops, and whatever the order of the gluing, the quotient is the same space. A
// graph with loops has no unique path between two nodes, so each segment of an edge the group
// shares with a later one carries its route: the arcs its path in its piece's disks runs along,
// mapped through every gluing and splicing since. Regular nodes no later gluing needs are spliced
// out at every stage: what a group sends grows with its border, not with its cells or its cuts.
#pragma once

#include "exact/piece_trees.hpp"
#include "tree/tree_result.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

// One side of an edge another group holds too: the group's nodes along it from its lower point
// (its ends and edge nodes), and for each segment between consecutive ones whether its path in
// its piece's disks rises (the total order (value, key) never falls along it) and, if so, that
// path's route in the group's graph. A segment that does not rise is glued at its ends only, and
// counted, as one process's gluing does.
struct ReebChain {
  NodeKey lo, hi;                   // the edge's ends (their nodes' keys), lower first
  std::array<int32_t, 2> span{};    // the pieces that may hold the edge
  std::vector<int64_t> nodes;       // indices into ReebGroup::nodes
  std::vector<uint8_t> rising;      // nodes.size() - 1 flags
  std::vector<int64_t> route_first; // segment k's arcs: route_arcs[first[k] .. first[k + 1])
  std::vector<int64_t> route_arcs;  // indices into ReebGroup::arcs, from the segment's lower end
};

struct ReebGroup {
  int32_t first_piece = 0, last_piece = 0;
  std::vector<PieceNode> nodes;             // ascending (value, key), one per key
  std::vector<std::array<int64_t, 2>> arcs; // lower index first, sorted; parallel arcs: loops
  std::vector<ReebChain> chains;            // by (lo, hi): edges the group does not hold whole
  ExactCounts counts;                       // the group's, each node of the uncut mesh counted once
  int64_t seam_edges = 0;
  int64_t nonmonotone = 0; // segments glued at their ends only (tree_stats)
};

// One piece's group from its reeb_piece: its disks' contour forest with its own cut glued back,
// reduced (`augmented`: every node stays).
ReebGroup reeb_group(const PieceTrees &piece, bool augmented);

// The same from a piece's kept trees of its disks (nodes ascending (value, key), the copies of
// one point next to each other; piece.chains unused) and the sides of its edges to glue:
// `chains`' nodes are indices into piece.nodes, their routes and flags left to fill.
ReebGroup reeb_group(const PieceTrees &piece, std::vector<ReebChain> chains, bool augmented);

// Groups a (pieces first .. k) and b (k + 1 .. last) as one, glued where they meet.
ReebGroup merge_reeb_groups(const ReebGroup &a, const ReebGroup &b, bool augmented);

// The whole mesh's Reeb graph from the group of all its pieces: values absolute (`reference`
// added back), the fallback stand-in's arcs contracted as exact_contour_tree does. Its
// seam_edges are the edges glued back (the pieces' cuts and the edges between pieces).
TreeResult reeb_graph_of_group(const ReebGroup &all, bool augmented, double reference);

} // namespace hoct
