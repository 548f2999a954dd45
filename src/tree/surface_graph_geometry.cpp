#include "tree/surface_graph_geometry.hpp"

namespace hoct {

Vec3 SurfaceGraphGeometry::node(int64_t v) const {
  const CellPoint &p = nodes_[v];
  return geometry_.position(p.cell, p.u, p.v);
}

void SurfaceGraphGeometry::edge_points(int64_t e, bool forward, std::vector<Vec3> &out) const {
  const EdgePiece &p = pieces_[e];
  if (geometry_.is_linear(p.cell))
    return;
  for (int j = 1; j <= kPiecePoints; ++j) {
    const double s = static_cast<double>(forward ? j : kPiecePoints + 1 - j) / (kPiecePoints + 1);
    out.push_back(geometry_.position(p.cell, p.u0 + (p.u1 - p.u0) * s, p.v0 + (p.v1 - p.v0) * s));
  }
}

} // namespace hoct
