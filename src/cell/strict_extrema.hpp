// Mesh vertices and edge nodes that are strict local extrema of the field, decided from the edge
// polynomials and the cells' inward derivatives: certain extrema, which no fallback may merge
// away (exact/degenerate_cells.hpp). A vertex whose every edge leaves it ascending (derivative
// beyond the tolerance) is a strict minimum: in each cell around it, the derivative along any
// direction of the corner's cone is a positive combination of those along its two edges. An edge
// node that is a strict minimum of its edge (a simple critical point, second derivative beyond
// the tolerance) where the field rises into every cell of the edge is one too. Maxima alike.
// The tolerance is 1e-9 of the field's value scale (relative values: mesh/field.hpp).
#pragma once

#include "cell/edge_nodes.hpp"
#include "mesh/field.hpp"
#include "mesh/topology.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

// Per mesh vertex: 1 a strict local minimum, 2 a strict local maximum, 0 neither; only the
// vertices `wanted` flags are decided (the others are 0).
std::vector<uint8_t> strict_vertex_extrema(const Topology &topology, const Field &field,
                                           const std::vector<uint8_t> &wanted);

// Whether node i (an index into edge_nodes.nodes) of edge e is a strict local extremum.
bool strict_edge_extremum(const Topology &topology, const Field &field, const EdgeNodes &edge_nodes,
                          int64_t e, int64_t i);

} // namespace hoct
