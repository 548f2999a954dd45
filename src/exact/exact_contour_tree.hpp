// The exact contour tree of a piecewise-polynomial field (the thesis' chapter 3, with certified
// connections; docs/ALGORITHM.md): nodes are the mesh vertices, the critical points of every edge
// and of every cell's interior; local connections are the edge chains and certified monotone
// paths from every sector inside a cell; degenerate cells fall back to a refinement through
// their edge nodes with the PL rule; the join and split graphs are swept once, globally, and
// merged. Every fallback is counted in the statistics.
#pragma once

#include "exact/exact_tree_options.hpp"
#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

namespace hoct {

TreeResult exact_contour_tree(const Mesh &mesh, const ExactTreeOptions &options = {});

} // namespace hoct
