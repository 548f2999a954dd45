// The reference triangle P0 = (0,0), P1 = (1,0), P2 = (0,1), in which every cell's polynomial
// lives; local edge k runs from corner k to corner k+1 (mod 3).
#pragma once

#include "util/vec.hpp"

namespace hoct {

// The corners, in order.
inline constexpr Vec2 kReferenceCorner[3] = {{0, 0}, {1, 0}, {0, 1}};

// Position on local edge k at parameter s from corner k.
Vec2 point_on_edge(int k, double s);
// Inward normal direction of local edge k (not normalised).
Vec2 inward_normal(int k);
// Direction of local edge k from corner k to corner k+1 (not normalised).
Vec2 edge_tangent(int k);

} // namespace hoct
