#include "exact/surface_graph_geometry.hpp"

#include <algorithm>

namespace hoct {

Vec3 SurfaceGraphGeometry::node(int64_t v) const {
  const CellPoint &p = nodes_[v];
  return geometry_.position(p.cell, p.u, p.v);
}

void SurfaceGraphGeometry::edge_points(int64_t e, bool forward, std::vector<Vec3> &out) const {
  const auto it = std::lower_bound(curved_ids_.begin(), curved_ids_.end(), e);
  if (it == curved_ids_.end() || *it != e)
    return; // a piece of a straight-sided cell: the segment between its ends
  const EdgePiece &p = curved_[static_cast<std::size_t>(it - curved_ids_.begin())];
  for (int j = 1; j <= kPiecePoints; ++j) {
    const double s = static_cast<double>(forward ? j : kPiecePoints + 1 - j) / (kPiecePoints + 1);
    out.push_back(geometry_.position(p.cell, p.u0 + (p.u1 - p.u0) * s, p.v0 + (p.v1 - p.v0) * s));
  }
}

} // namespace hoct
