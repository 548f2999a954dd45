// The local connections of one non-degenerate cell: for every lower sector of its nodes that
// lies inside the cell (interior maxima and saddles, edge nodes whose interior descends while the
// edge ascends), a certified path to a lower node; the same for upper sectors. Sectors along an
// edge are covered by the edge chains and need no path (docs/ALGORITHM.md §3).
#pragma once

#include "cell/cell_nodes.hpp"
#include "cell/certified_path.hpp"
#include "cell/degenerate_points.hpp"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace hoct {

struct InteriorCritical {
  Vec2 uv;
  double value;
  int32_t degenerate = -1; // its sectors, if a degenerate point: an index the caller resolves
  int32_t curve = -1;      // the same for a critical curve (cell/critical_curves.hpp)
};

// An edge node of the cell as classification needs it.
struct CellEdgeNode {
  int local_edge;
  double s;      // parameter along the local edge from its first corner
  double second; // second derivative of the edge polynomial (orientation-independent)
  int node;      // index into CellNodes::nodes
};

struct SectorResult {
  std::vector<std::pair<int64_t, int64_t>> join, split; // node refs (see LocalNode::ref)
  // With paths requested: the certified polyline of each join / split connection.
  std::vector<std::vector<Vec2>> join_paths, split_paths;
  bool failed = false;     // some sector could not be connected: fall back
  bool degenerate = false; // an edge node with vanishing normal derivative: fall back
};

// The result goes to `out` (cleared first; its storage is reused from cell to cell).
// `rays`, if not empty, runs parallel to `interior_nodes`: a degenerate critical point's sectors
// (cell/degenerate_points.hpp), each connected along the ray to its point; null for a regular
// critical point, whose sectors follow from its Hessian. `corner_rays[k]`: the sectors inside the
// cell of a critical corner k (resolve_critical_corners), each connected along its ray.
void connect_sectors(const BernsteinTriangle &g, const CellNodes &nodes,
                     const std::vector<int> &interior_nodes,
                     const std::vector<CellEdgeNode> &edge_nodes, PathCounters &counters,
                     SectorResult &out, bool with_paths = false,
                     std::span<const SectorRays *const> rays = {},
                     const std::array<const SectorRays *, 3> &corner_rays = {});

} // namespace hoct
