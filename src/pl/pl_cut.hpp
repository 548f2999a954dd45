// A piecewise-linear mesh cut open into disks, for its Reeb graph (docs/ALGORITHM.md §7): the
// cut of the exact field (mesh/cut_surface) on the PL mesh's own triangles. The PL tree of the
// disks, glued back along the seams (tree/path_gluing), is the PL Reeb graph.
#pragma once

#include "pl/pl_mesh.hpp"
#include "tree/path_gluing.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

struct PlCut {
  // The disks: per vertex its value and the point of the PL mesh it is a copy of (ascending,
  // so the total order (value, id) is the PL mesh's); triangles by the disks' vertex ids.
  std::vector<double> values;
  std::vector<int64_t> point;
  std::vector<std::array<int64_t, 3>> triangles;
  // The copies of each vertex on the cut are one point; each cut edge's two copies one curve.
  PathGluing gluing;
  // The vertices on the seams: kept in the reduced tree for the gluing to find.
  std::vector<uint8_t> keep;
  int64_t seam_edges = 0;
};

// The mesh cut open along a cut graph of its own triangles; no triangles and no seams when every
// component is a disk or a sphere (nothing to cut). Throws hoct::Error if the triangles are not a
// surface or the cut does not give disks (which the higher-order mesh's checks rule out).
PlCut cut_pl_mesh(const PlMesh &mesh, int threads = 1);

} // namespace hoct
