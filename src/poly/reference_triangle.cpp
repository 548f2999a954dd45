#include "poly/reference_triangle.hpp"

namespace hoct {

Vec2 point_on_edge(int k, double s) {
  const Vec2 &a = kReferenceCorner[k], &b = kReferenceCorner[(k + 1) % 3];
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])};
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
