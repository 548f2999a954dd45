#include "pl/refinement.hpp"

#include "pl/cell_refinement.hpp"
#include "poly/lattice.hpp"
#include "poly/reference_triangle.hpp"
#include "util/error.hpp"

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
  const bool has_extra = !opt.edge_points.empty();
  if (has_extra && static_cast<int64_t>(opt.edge_points.size()) != ne)
    throw Error("refine: edge_points must have one list per edge");

  PlMesh pl;
  pl.reference = field.reference();
  auto add = [&](int64_t cell, double u, double v, double value) {
    pl.points.push_back(geom.position(cell, u, v));
    pl.values.push_back(value);
    pl.source_cell.push_back(cell);
    pl.source_uv.push_back({u, v});
    return static_cast<int64_t>(pl.values.size() - 1);
  };
  // Vertices first: PL vertex id = mesh vertex id.
  for (int64_t v = 0; v < nv; ++v)
    add(topo.vertex_cell(v), kReferenceCorner[topo.vertex_corner(v)][0],
        kReferenceCorner[topo.vertex_corner(v)][1], field.vertex_value(v));

  // Each edge's extra points (lo -> hi parameters, sorted, off the lattice), and the PL ids of
  // its lattice points (steps 1..k-1 from lo) and extra points, created once per edge.
  std::vector<std::vector<double>> extra(ne);
  std::vector<int64_t> lattice_id(static_cast<std::size_t>(ne) * std::max(k - 1, 0), -1);
  std::vector<std::vector<int64_t>> extra_id(ne);
  for (int64_t e = 0; e < ne; ++e) {
    if (has_extra)
      for (double t : opt.edge_points[e]) {
        const double nearest = std::round(t * k) / k;
        if (t > 1e-12 && t < 1 - 1e-12 && std::abs(t - nearest) > 1e-12)
          extra[e].push_back(t);
      }
    std::sort(extra[e].begin(), extra[e].end());
    extra[e].erase(std::unique(extra[e].begin(), extra[e].end(),
                               [](double a, double b) { return b - a <= 1e-12; }),
                   extra[e].end());
    // Positions through the first cell of the edge.
    const int64_t c = topo.edge_cells_begin(e)[0];
    const int lk = topo.local_edge(c, e);
    const bool rev = topo.edge_reversed(c, lk);
    const BernsteinPoly p = field.edge_polynomial(e);
    auto at = [&](double t) {
      const double s = rev ? 1 - t : t;
      const Vec2 uv = point_on_edge(lk, s);
      return add(c, uv[0], uv[1], p(t));
    };
    for (int s = 1; s < k; ++s)
      lattice_id[static_cast<std::size_t>(e) * (k - 1) + (s - 1)] = at(static_cast<double>(s) / k);
    for (double t : extra[e])
      extra_id[e].push_back(at(t));
  }

  std::array<std::vector<double>, 3> local_extra;
  std::vector<int64_t> ids;
  for (int64_t c = 0; c < nc; ++c) {
    for (int j = 0; j < 3; ++j) {
      const int64_t e = topo.cell_edge(c, j);
      local_extra[j] = extra[e];
      if (topo.edge_reversed(c, j)) {
        for (double &t : local_extra[j])
          t = 1 - t;
        std::reverse(local_extra[j].begin(), local_extra[j].end());
      }
    }
    const CellRefinement cr = refine_cell(k, local_extra);
    const BernsteinTriangle poly = field.cell_polynomial(c);
    ids.resize(cr.vertices.size());
    for (std::size_t i = 0; i < cr.vertices.size(); ++i) {
      const CellSubVertex &sv = cr.vertices[i];
      switch (sv.kind) {
      case CellSubVertex::Kind::Corner:
        ids[i] = topo.cell_vertices(c)[sv.corner];
        break;
      case CellSubVertex::Kind::EdgeLattice: {
        const int64_t e = topo.cell_edge(c, sv.edge);
        const int s = topo.edge_reversed(c, sv.edge) ? k - sv.index : sv.index;
        ids[i] = lattice_id[static_cast<std::size_t>(e) * (k - 1) + (s - 1)];
        break;
      }
      case CellSubVertex::Kind::EdgeExtra: {
        const int64_t e = topo.cell_edge(c, sv.edge);
        const int n = static_cast<int>(extra_id[e].size());
        ids[i] = extra_id[e][topo.edge_reversed(c, sv.edge) ? n - 1 - sv.index : sv.index];
        break;
      }
      case CellSubVertex::Kind::Interior:
        ids[i] = add(c, sv.u, sv.v, poly(sv.u, sv.v));
        break;
      }
    }
    for (const auto &t : cr.triangles)
      pl.triangles.push_back({ids[t[0]], ids[t[1]], ids[t[2]]});
  }
  return pl;
}

} // namespace hoct
