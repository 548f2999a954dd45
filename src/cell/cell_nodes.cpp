#include "cell/cell_nodes.hpp"

namespace hoct {

Vec2 point_on_edge(int k, double s) {
  static constexpr double kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  const int j = (k + 1) % 3;
  return {kCorner[k][0] + s * (kCorner[j][0] - kCorner[k][0]),
          kCorner[k][1] + s * (kCorner[j][1] - kCorner[k][1])};
}

Vec2 inward_normal(int k) {
  switch (k) {
  case 0:
    return {0, 1};
  case 1:
    return {-1, -1};
  default:
    return {1, 0};
  }
}

Vec2 edge_tangent(int k) {
  switch (k) {
  case 0:
    return {1, 0};
  case 1:
    return {-1, 1};
  default:
    return {0, -1};
  }
}

} // namespace hoct
