// The piecewise-linear contour tree of a PlMesh, reported as a TreeResult (positions, types,
// where each node sits in the higher-order mesh, persistence pairs, timings).
#pragma once

#include "pl/pl_mesh.hpp"
#include "tree/tree_result.hpp"

#include <string>

namespace hoct {

// With `reeb`, the Reeb graph: the mesh cut open into disks (pl/pl_cut) and their tree glued back
// along the seams, for a domain that is not a disk or a sphere (on one, the contour tree).
// With `with_graph`, the mesh's 1-skeleton is kept as the result's geometric graph (to draw arcs).
// `threads` (0: all cores) >= 2 runs the join and the split sweep at once on large meshes (the
// result does not depend on it).
TreeResult pl_contour_tree(const PlMesh &mesh, bool augmented, const std::string &method,
                           bool with_graph = false, int threads = 1, bool reeb = false);

} // namespace hoct
