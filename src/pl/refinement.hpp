// Exact refinement of a higher-order mesh into linear triangles: every cell split into k x k
// sub-triangles of its reference lattice (conforming: sub-vertices on a shared edge are shared),
// values evaluated from the exact field (edge points from the shared edge polynomial, so both
// neighbours agree bit-for-bit), positions through the geometry map. Optionally, extra points on
// edges (e.g. edge critical points) are inserted as sub-vertices.
#pragma once

#include "mesh/mesh.hpp"
#include "pl/pl_mesh.hpp"

#include <vector>

namespace hoct {

struct RefinementOptions {
  int k = 1;
  // Extra points per global edge, as parameters t in (0, 1) from the edge's lower to its higher
  // vertex (empty = none). Points within 1e-12 of a lattice point reuse it.
  std::vector<std::vector<double>> edge_points;
};

PlMesh refine(const Mesh &mesh, const RefinementOptions &options);
inline PlMesh refine(const Mesh &mesh, int k) {
  RefinementOptions o;
  o.k = k;
  return refine(mesh, o);
}

} // namespace hoct
