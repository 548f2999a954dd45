// The nodes of one cell as its local computations see them: its three vertices, the critical
// points of its three edges, its interior critical points, each with its position in the
// reference triangle, its value, and a reference to its global node; and, per local edge, the
// chain of nodes along the edge (between consecutive chain nodes the edge is monotone).
#pragma once

#include "poly/bernstein_triangle.hpp"
#include "poly/reference_triangle.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

struct LocalNode {
  Vec2 uv{0, 0};
  double value = 0;
  int64_t ref = -1; // global node id, or -(1 + i) for this cell's i-th interior node
};

struct CellNodes {
  std::vector<LocalNode> nodes;
  // chain[k]: indices into nodes along local edge k from corner k to corner k+1; chain_s[k]: the
  // parameter of each along the edge (0 at corner k, 1 at corner k+1).
  std::array<std::vector<int>, 3> chain;
  std::array<std::vector<double>, 3> chain_s;
};

} // namespace hoct
