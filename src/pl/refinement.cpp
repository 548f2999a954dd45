#include "pl/refinement.hpp"

#include "error.hpp"
#include "poly/lattice.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {

PlMesh refine(const Mesh &mesh, const RefinementOptions &opt) {
  const int k = opt.k;
  if (k < 1 || k > 1024)
    throw Error("refinement level must be between 1 and 1024, got " + std::to_string(k));
  const Topology &topo = mesh.topology;
  const Field &field = mesh.field;
  const Geometry &geom = mesh.geometry;
  const int64_t nv = topo.num_vertices(), ne = topo.num_edges(), nc = topo.num_cells();
  const bool extra = !opt.edge_points.empty();
  if (extra && static_cast<int64_t>(opt.edge_points.size()) != ne)
    throw Error("refine: edge_points must have one list per edge");

  PlMesh pl;
  auto add = [&](const Vec3 &p, double value, int64_t cell, double u, double v) {
    pl.points.push_back(p);
    pl.values.push_back(value);
    pl.source_cell.push_back(cell);
    pl.source_uv.push_back({u, v});
    return static_cast<int64_t>(pl.values.size() - 1);
  };
  // Any cell at a vertex, and where the vertex sits in it.
  std::vector<int64_t> vertex_cell(nv, -1);
  std::vector<int> vertex_corner(nv, 0);
  for (int64_t c = nc - 1; c >= 0; --c)
    for (int j = 0; j < 3; ++j) {
      vertex_cell[topo.cell_vertices(c)[j]] = c;
      vertex_corner[topo.cell_vertices(c)[j]] = j;
    }
  static constexpr double kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (int64_t v = 0; v < nv; ++v) {
    const int64_t c = vertex_cell[v];
    const double u = kCorner[vertex_corner[v]][0], w = kCorner[vertex_corner[v]][1];
    add(geom.position(c, u, w), field.vertex_value(v), c, u, w);
  }
  // Edge points: the k-1 lattice points, merged with the extra points, sorted by t (lo -> hi).
  std::vector<int64_t> edge_offset(ne + 1, 0);
  std::vector<double> edge_t;    // t of each edge sub-vertex (lo -> hi)
  std::vector<int64_t> edge_vid; // its PL vertex id
  std::vector<char> edge_is_lattice;
  std::vector<double> ts;
  for (int64_t e = 0; e < ne; ++e) {
    ts.clear();
    for (int s = 1; s < k; ++s)
      ts.push_back(static_cast<double>(s) / k);
    if (extra)
      for (double t : opt.edge_points[e])
        if (t > 1e-12 && t < 1 - 1e-12)
          ts.push_back(t);
    std::sort(ts.begin(), ts.end());
    // The owner cell: the first incident cell; parameter along its local edge.
    const int64_t c = topo.edge_cells_begin(e)[0];
    int lk = 0;
    while (topo.cell_edge(c, lk) != e)
      ++lk;
    const bool rev = topo.edge_reversed(c, lk);
    const BernsteinPoly p = field.edge_polynomial(e);
    double last = -1;
    for (double t : ts) {
      const bool lattice = std::abs(t * k - std::round(t * k)) < 1e-12 * k;
      if (t - last < 1e-12) {
        if (lattice) // keep the lattice point's exact parameter
          edge_t.back() = t, edge_is_lattice.back() = 1;
        continue;
      }
      last = t;
      const double s = rev ? 1 - t : t; // along the cell's local edge
      const double u = kCorner[lk][0] + s * (kCorner[(lk + 1) % 3][0] - kCorner[lk][0]);
      const double w = kCorner[lk][1] + s * (kCorner[(lk + 1) % 3][1] - kCorner[lk][1]);
      edge_t.push_back(t);
      edge_is_lattice.push_back(lattice);
      edge_vid.push_back(add(geom.position(c, u, w), p(t), c, u, w));
    }
    edge_offset[e + 1] = static_cast<int64_t>(edge_t.size());
  }

  // Cells: interior lattice points, then sub-triangles, fanning at boundary sub-edges that carry
  // extra points.
  std::vector<int64_t> local(lattice_size(k));
  std::vector<int64_t> between;
  for (int64_t c = 0; c < nc; ++c) {
    const BernsteinTriangle poly = field.cell_polynomial(c);
    for (int b = 0; b <= k; ++b)
      for (int a = 0; a + b <= k; ++a) {
        const int idx = lattice_index(k, a, b);
        const int ki = (a == 0 && b == 0) ? 0 : (a == k ? 1 : (b == k ? 2 : -1));
        if (ki >= 0) {
          local[idx] = topo.cell_vertices(c)[ki];
          continue;
        }
        int lk = -1, s = 0;
        if (b == 0)
          lk = 0, s = a;
        else if (a + b == k)
          lk = 1, s = b;
        else if (a == 0)
          lk = 2, s = k - b;
        if (lk >= 0) {
          const int64_t e = topo.cell_edge(c, lk);
          const double t = topo.edge_reversed(c, lk) ? 1.0 - static_cast<double>(s) / k
                                                     : static_cast<double>(s) / k;
          // The lattice sub-vertex of this edge with parameter t.
          int64_t found = -1;
          for (int64_t i = edge_offset[e]; i < edge_offset[e + 1]; ++i)
            if (edge_is_lattice[i] && std::abs(edge_t[i] - t) < 1e-9) {
              found = edge_vid[i];
              break;
            }
          local[idx] = found;
          continue;
        }
        const double u = static_cast<double>(a) / k, v = static_cast<double>(b) / k;
        local[idx] = add(geom.position(c, u, v), poly(u, v), c, u, v);
      }
    // Sub-vertices strictly between two boundary lattice neighbours p -> q on local edge lk.
    auto edge_between = [&](int lk, int64_t p, int64_t q) {
      between.clear();
      if (!extra)
        return;
      const int64_t e = topo.cell_edge(c, lk);
      double tp = -1, tq = -1;
      for (int64_t i = edge_offset[e]; i < edge_offset[e + 1]; ++i) {
        if (edge_vid[i] == p)
          tp = edge_t[i];
        if (edge_vid[i] == q)
          tq = edge_t[i];
      }
      const auto &ev = topo.edge_vertices(e);
      if (p == ev[0])
        tp = 0;
      if (p == ev[1])
        tp = 1;
      if (q == ev[0])
        tq = 0;
      if (q == ev[1])
        tq = 1;
      for (int64_t i = edge_offset[e]; i < edge_offset[e + 1]; ++i)
        if (std::min(tp, tq) < edge_t[i] && edge_t[i] < std::max(tp, tq))
          between.push_back(edge_vid[i]);
      if (tp > tq)
        std::reverse(between.begin(), between.end());
    };
    // Upward triangle (a,b), (a+1,b), (a,b+1): its sides lie on local edges 0 (b == 0),
    // 1 (a + b + 1 == k) and 2 (a == 0). With extra points on one side, fan from the opposite
    // corner; on two or more sides (corners of the cell), fan from a new centre vertex.
    // Downward triangles never have a whole side on the cell boundary.
    std::vector<int64_t> ring;
    for (int b = 0; b < k; ++b)
      for (int a = 0; a + b < k; ++a) {
        const int64_t corner[3] = {local[lattice_index(k, a, b)], local[lattice_index(k, a + 1, b)],
                                   local[lattice_index(k, a, b + 1)]};
        const bool on_edge[3] = {b == 0, a + b + 1 == k, a == 0};
        ring.clear();
        int sides_with_points = 0, split_side = -1;
        for (int j = 0; j < 3; ++j) {
          ring.push_back(corner[j]);
          if (on_edge[j]) {
            edge_between(j, corner[j], corner[(j + 1) % 3]);
            if (!between.empty()) {
              ++sides_with_points;
              split_side = j;
              ring.insert(ring.end(), between.begin(), between.end());
            }
          }
        }
        if (sides_with_points == 0) {
          pl.triangles.push_back({corner[0], corner[1], corner[2]});
        } else if (sides_with_points == 1) {
          // Rotate the ring to start at the corner opposite the split side, then fan.
          const int64_t apex = corner[(split_side + 2) % 3];
          const auto it = std::find(ring.begin(), ring.end(), apex);
          std::rotate(ring.begin(), it, ring.end());
          for (std::size_t i = 1; i + 1 < ring.size(); ++i)
            pl.triangles.push_back({ring[0], ring[i], ring[i + 1]});
        } else {
          const double u = (3.0 * a + 1) / (3.0 * k), v = (3.0 * b + 1) / (3.0 * k);
          const int64_t centre = add(geom.position(c, u, v), poly(u, v), c, u, v);
          for (std::size_t i = 0; i < ring.size(); ++i)
            pl.triangles.push_back({ring[i], ring[(i + 1) % ring.size()], centre});
        }
        if (a + b + 1 < k)
          pl.triangles.push_back({corner[1], local[lattice_index(k, a + 1, b + 1)], corner[2]});
      }
  }
  return pl;
}

} // namespace hoct
