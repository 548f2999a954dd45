// A contour tree glued into a Reeb graph along identified monotone paths (docs/ALGORITHM.md §7).
//
// The Reeb graph of a surface cut open into disks is the contour tree of the disks with the
// seams glued back: where the cut separated two copies of one curve, their level-set
// components are one. Each seam piece is a monotone curve, mapped onto the tree's (unique,
// monotone) path between its ends; its two copies are identified point by point at equal
// values. Gluing subdivides the arcs of those paths at the levels of the nodes on the paths
// they are glued to (the cuts spread along chains of glued arcs until every glued pair of arcs
// is cut at the same levels), then takes the quotient: nodes and sub-arcs identified by union-find,
// parallel arcs kept (they are the loops), regular nodes spliced out.
#pragma once

#include "tree/contour_tree.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

struct PathGluing {
  // Groups of nodes that are one point (ids of the graph the tree came from, as in
  // ContourTree::nodes): group i is members[offset[i] .. offset[i + 1]).
  std::vector<int64_t> group_offset{0}, group_members;
  // Curves that are one: the tree's path from a1 to b1 and its path from a2 to b2, given as
  // {a1, b1, a2, b2} (a1 and a2 one point, b1 and b2 one point, a below b), identified point by
  // point at equal values.
  std::vector<std::array<int64_t, 4>> paths;
  // Optional, one per path: the arcs (indices into the graph's arcs) of its two sides, each from
  // its lower end. Without them the graph must be a forest, and each side is its unique path
  // there. A graph with loops (a Reeb graph glued in stages, exact/reeb_group) has no unique
  // path, so its caller says which one each curve runs along.
  std::vector<std::array<std::vector<int64_t>, 2>> routes;
};

struct GluedGraph {
  // Reduced, nodes ascending in the total order, arcs lower node first; parallel arcs where the
  // level sets make loops. Each node stands for its group; its id is the group's lowest node.
  ContourTree graph;
  // Paths whose values do not rise along the tree (a tie between copies and other nodes of equal
  // value): their ends are glued, their interiors are not. Counted, never expected.
  int64_t nonmonotone_paths = 0;
  // Unreduced only: each input node's node in `graph`, and each input arc's arcs there (the
  // pieces it was cut into, from its lower end).
  std::vector<int64_t> node_of;
  std::vector<std::vector<int64_t>> arc_image;
};

// `reduced`: regular nodes spliced out (else every node of the tree is kept, as its group).
// Throws std::invalid_argument for a node that is not in the tree, a path between components or
// a route that does not run between its ends.
GluedGraph glue_paths(const ContourTree &tree, const PathGluing &gluing, bool reduced = true);

// The forest's path from ends[i][0] to ends[i][1] (indices into its nodes), as its arcs in order.
// Throws std::invalid_argument for a path between components.
std::vector<std::vector<int64_t>> forest_paths(const ContourTree &forest,
                                               const std::vector<std::array<int64_t, 2>> &ends);

} // namespace hoct
