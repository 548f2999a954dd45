#include "cell/strict_extrema.hpp"

#include "poly/reference_triangle.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {
namespace {

double slope_tolerance(const Field &field) { return 1e-9 * field.value_scale(); }

} // namespace

std::vector<uint8_t> strict_vertex_extrema(const Topology &topo, const Field &field,
                                           const std::vector<uint8_t> &wanted) {
  const double tol = slope_tolerance(field);
  // Bit 0: every edge so far ascends away from the vertex; bit 1: every edge descends.
  std::vector<uint8_t> all(static_cast<std::size_t>(topo.num_vertices()), 3);
  std::vector<uint8_t> seen(static_cast<std::size_t>(topo.num_vertices()), 0);
  for (int64_t e = 0; e < topo.num_edges(); ++e) {
    const auto &ends = topo.edge_vertices(e);
    if (!wanted[ends[0]] && !wanted[ends[1]])
      continue;
    const auto c = field.edge_coefficients(e);
    const int d = static_cast<int>(c.size()) - 1;
    for (int end = 0; end < 2; ++end) {
      const int64_t v = ends[end];
      seen[v] = 1;
      if (d < 1) {
        all[v] = 0;
        continue;
      }
      const double slope = end == 0 ? d * (c[1] - c[0]) : d * (c[d - 1] - c[d]);
      if (!(slope > tol))
        all[v] &= uint8_t(~1u);
      if (!(slope < -tol))
        all[v] &= uint8_t(~2u);
    }
  }
  std::vector<uint8_t> out(all.size(), 0);
  for (std::size_t v = 0; v < all.size(); ++v)
    out[v] = !seen[v] || !wanted[v] ? 0 : (all[v] & 1) ? 1 : (all[v] & 2) ? 2 : 0;
  return out;
}

bool strict_edge_extremum(const Topology &topo, const Field &field, const EdgeNodes &en, int64_t e,
                          int64_t i) {
  if (en.degeneracy[e] != kEdgeOk)
    return false;
  const double tol = slope_tolerance(field);
  const EdgeNode &node = en.nodes[i];
  if (!node.simple || !(std::abs(node.second) > tol))
    return false;
  const bool minimum = node.second > 0;
  for (int j = 0; j < topo.edge_cell_count(e); ++j) {
    const int64_t c = topo.edge_cells_begin(e)[j];
    const int k = topo.local_edge(c, e);
    const Vec2 uv = point_on_edge(k, topo.edge_reversed(c, k) ? 1 - node.t : node.t);
    const Vec2 g = field.cell_polynomial(c).gradient(uv[0], uv[1]);
    const Vec2 n = inward_normal(k);
    const double inward = g[0] * n[0] + g[1] * n[1];
    if (minimum ? !(inward > tol) : !(inward < -tol))
      return false;
  }
  return true;
}

} // namespace hoct
