// A geometric graph's geometry on a mesh's surface: its nodes as points of cells, its first
// edges as straight pieces of mesh edges in their cells' reference triangles (the edge chains),
// both mapped to the surface by the mesh's geometry only when a path is drawn through them.
#pragma once

#include "mesh/geometry.hpp"
#include "tree/geometric_graph.hpp"
#include "util/uninitialized_vector.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

// A point of a cell: the cell and reference coordinates (u, v).
struct CellPoint {
  int64_t cell;
  double u, v;
};

// A piece of a mesh edge in one cell, from (u0, v0) to (u1, v1) in its reference triangle.
struct EdgePiece {
  int64_t cell;
  double u0, v0, u1, v1;
};

class SurfaceGraphGeometry final : public GraphGeometry {
public:
  // Points drawn strictly inside each piece of a curved cell; on a straight-sided cell the
  // piece is a straight segment between its ends and has none.
  static constexpr int kPiecePoints = 3;

  // Graph node v lies at nodes[v]; graph edges [0, edges) are pieces of mesh edges, of which
  // edges curved_ids[i] (ascending) lie in curved cells, along curved[i]; the others in
  // straight-sided cells. `geometry` is shared, not copied (Geometry's maps are).
  SurfaceGraphGeometry(Geometry geometry, UninitializedVector<CellPoint> nodes, int64_t edges,
                       UninitializedVector<int64_t> curved_ids,
                       UninitializedVector<EdgePiece> curved)
      : geometry_(std::move(geometry)), nodes_(std::move(nodes)), edges_(edges),
        curved_ids_(std::move(curved_ids)), curved_(std::move(curved)) {}

  Vec3 node(int64_t v) const override;
  int64_t edges() const override { return edges_; }
  void edge_points(int64_t e, bool forward, std::vector<Vec3> &out) const override;

private:
  Geometry geometry_;
  UninitializedVector<CellPoint> nodes_;
  int64_t edges_;
  UninitializedVector<int64_t> curved_ids_;
  UninitializedVector<EdgePiece> curved_;
};

} // namespace hoct
