// Critical points of every mesh edge: the roots in (0, 1) of the derivative of the edge's
// polynomial (computed once per edge, so both cells of the edge use the same nodes), found by a
// root isolation that cannot miss a simple root (poly/root_isolation.hpp). Degenerate edges
// (constant edge, a critical point at or next to a vertex, a multiple root) are flagged.
#pragma once

#include "mesh/field.hpp"
#include "mesh/topology.hpp"
#include "util/uninitialized_vector.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

struct EdgeNode {
  double t;      // parameter from the edge's lower to its higher vertex
  double value;  // the edge polynomial at t
  double second; // second derivative of the edge polynomial at t (d^2/dt^2)
  bool simple;   // a certified simple root of the derivative
};

enum EdgeDegeneracy : uint8_t {
  kEdgeOk = 0,
  kEdgeConstant = 1,          // the edge polynomial is constant
  kEdgeRootAtVertex = 2,      // the derivative vanishes at (or within tolerance of) a vertex
  kEdgeMultipleRoot = 4,      // clustered or multiple roots of the derivative
  kEdgeFlatCriticalPoint = 8, // |second derivative| below tolerance at a root
};

struct EdgeNodes {
  UninitializedVector<int64_t> offset;     // nodes of edge e: nodes[offset[e] .. offset[e+1])
  UninitializedVector<EdgeNode> nodes;     // ascending t within each edge
  UninitializedVector<uint8_t> degeneracy; // EdgeDegeneracy bits per edge

  int64_t count(int64_t e) const { return offset[e + 1] - offset[e]; }
};

struct EdgeNodeOptions {
  double vertex_tolerance = 1e-9; // a root this close to t = 0 or 1 is "at the vertex"
  double flat_tolerance = 1e-8;   // |p''| * (edge scale) below this * value scale: flat
  int threads = 1;                // edges are independent: any thread count, same result
};

EdgeNodes find_edge_nodes(const Topology &topology, const Field &field,
                          const EdgeNodeOptions &options = {});

} // namespace hoct
