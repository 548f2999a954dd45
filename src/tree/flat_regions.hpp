// Flat regions. On plateaus and ridges many nodes share one value; the total order (value, id)
// makes a tree of them with arcs of length zero, and leaf branches of persistence zero: artefacts
// of the tie-breaking, not features. Contracting every arc whose ends have the same value (within
// `tolerance`: values computed from a constant polynomial differ by rounding)
// merges each flat region into one node (docs/ALGORITHM.md §4: a critical curve component is one
// node) and leaves the tree valid; regular nodes left over are spliced out.
#pragma once

#include "tree/contour_tree.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

struct FlatContraction {
  ContourTree tree;
  std::vector<int64_t> kept; // for each node of the result, the input node representing it
  std::vector<int64_t> size; // for each node of the result, the input nodes of its flat region
};

FlatContraction contract_flat_arcs(const ContourTree &tree, double tolerance = 0);

} // namespace hoct
