#include "pl/cell_refinement.hpp"

#include "poly/lattice.hpp"
#include "poly/reference_triangle.hpp"

#include <algorithm>

namespace hoct {

CellRefinement refine_cell(int k, const std::array<std::vector<double>, 3> &extra) {
  CellRefinement r;
  std::vector<int> local(lattice_size(k));
  auto edge_point = [](int e, double s) { return point_on_edge(e, s); };
  for (int b = 0; b <= k; ++b)
    for (int a = 0; a + b <= k; ++a) {
      CellSubVertex sv;
      sv.u = static_cast<double>(a) / k;
      sv.v = static_cast<double>(b) / k;
      if (a == 0 && b == 0) {
        sv.kind = CellSubVertex::Kind::Corner, sv.corner = 0;
      } else if (a == k) {
        sv.kind = CellSubVertex::Kind::Corner, sv.corner = 1;
      } else if (b == k) {
        sv.kind = CellSubVertex::Kind::Corner, sv.corner = 2;
      } else if (b == 0) {
        sv.kind = CellSubVertex::Kind::EdgeLattice, sv.edge = 0, sv.index = a;
      } else if (a + b == k) {
        sv.kind = CellSubVertex::Kind::EdgeLattice, sv.edge = 1, sv.index = b;
      } else if (a == 0) {
        sv.kind = CellSubVertex::Kind::EdgeLattice, sv.edge = 2, sv.index = k - b;
      } else {
        sv.kind = CellSubVertex::Kind::Interior;
      }
      local[lattice_index(k, a, b)] = static_cast<int>(r.vertices.size());
      r.vertices.push_back(sv);
    }
  // Extra edge points, and for each edge the sub-vertices strictly between lattice steps.
  std::array<std::vector<std::pair<double, int>>, 3> on_edge; // (s, vertex) of extra points
  for (int e = 0; e < 3; ++e)
    for (std::size_t i = 0; i < extra[e].size(); ++i) {
      CellSubVertex sv;
      sv.kind = CellSubVertex::Kind::EdgeExtra;
      sv.edge = e;
      sv.index = static_cast<int>(i);
      const auto p = edge_point(e, extra[e][i]);
      sv.u = p[0];
      sv.v = p[1];
      on_edge[e].push_back({extra[e][i], static_cast<int>(r.vertices.size())});
      r.vertices.push_back(sv);
    }
  auto between = [&](int e, int step, std::vector<int> &out) {
    // Extra points with s in (step/k, (step+1)/k), in increasing s.
    out.clear();
    const double lo = static_cast<double>(step) / k, hi = static_cast<double>(step + 1) / k;
    for (const auto &[s, vid] : on_edge[e])
      if (s > lo && s < hi)
        out.push_back(vid);
  };
  std::vector<int> ring, mid;
  for (int b = 0; b < k; ++b)
    for (int a = 0; a + b < k; ++a) {
      const int corner[3] = {local[lattice_index(k, a, b)], local[lattice_index(k, a + 1, b)],
                             local[lattice_index(k, a, b + 1)]};
      // Sides of this upward sub-triangle that lie on the cell's edges, with the step index
      // of the side along that edge (from the edge's first corner).
      const bool on[3] = {b == 0, a + b + 1 == k, a == 0};
      const int step[3] = {a, b, k - 1 - b};
      ring.clear();
      int split_sides = 0, split_side = -1;
      for (int j = 0; j < 3; ++j) {
        ring.push_back(corner[j]);
        if (on[j]) {
          between(j, step[j], mid);
          if (!mid.empty()) {
            ++split_sides;
            split_side = j;
            ring.insert(ring.end(), mid.begin(), mid.end());
          }
        }
      }
      if (split_sides == 0) {
        r.triangles.push_back({corner[0], corner[1], corner[2]});
      } else if (split_sides == 1) {
        const int apex = corner[(split_side + 2) % 3];
        std::rotate(ring.begin(), std::find(ring.begin(), ring.end(), apex), ring.end());
        for (std::size_t i = 1; i + 1 < ring.size(); ++i)
          r.triangles.push_back({ring[0], ring[i], ring[i + 1]});
      } else {
        // Split on two or three sides: fan from a new centre vertex.
        CellSubVertex c;
        c.kind = CellSubVertex::Kind::Interior;
        c.u = (3.0 * a + 1) / (3.0 * k);
        c.v = (3.0 * b + 1) / (3.0 * k);
        const int centre = static_cast<int>(r.vertices.size());
        r.vertices.push_back(c);
        for (std::size_t i = 0; i < ring.size(); ++i)
          r.triangles.push_back({ring[i], ring[(i + 1) % ring.size()], centre});
      }
      if (a + b + 1 < k)
        r.triangles.push_back({corner[1], local[lattice_index(k, a + 1, b + 1)], corner[2]});
    }
  return r;
}

} // namespace hoct
