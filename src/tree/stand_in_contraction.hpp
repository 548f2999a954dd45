// Where a degenerate cell's PL stand-in replaces the field (exact/degenerate_cells.hpp), the tree
// may be off by the stand-in's certified distance from the field: a ridge (a critical curve) is
// broken into maxima and saddles along it, a degenerate critical point into a spurious pair, a
// join that happens on the ridge happens a little below it. Every such artefact is an arc
// between two stand-in nodes no longer than twice that distance (the stability of persistence
// diagrams). Contracting those arcs, shortest first, merges each broken critical curve into one
// node and cancels the spurious pairs; no node's group spans more than twice the distance in
// value, so the result stays within it of the stand-in's tree (docs/ALGORITHM.md §4).
#pragma once

#include "tree/contour_tree.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

struct StandInContraction {
  ContourTree tree;       // contracted and reduced; node ids as the input's
  int64_t contracted = 0; // arcs contracted
};

// slack[i]: the stand-in's distance from the field around node i of `tree` (its index), or a
// negative number for a node the stand-in did not make. An arc (a, b) is contracted if both ends
// have a slack, it is longer than zero and at most 2 max(slack) long, and the nodes merged into
// one stay within that of each other (arcs of length zero, of plateaus and of ridges of exactly
// equal values, are left to contract_flat, which --keep-flat turns off). The merged node keeps the
// value and id of the end whose value keeps every arc monotone (the higher one where the lower had
// no other arc up, else the lower one where the higher had no other arc down); nodes left regular
// are spliced out; the global minimum and maximum stay.
StandInContraction contract_stand_in_arcs(const ContourTree &tree,
                                          const std::vector<double> &slack);

} // namespace hoct
