#include "pl/pl_mesh.hpp"

#include "mesh/cell_split.hpp"

#include "poly/lattice.hpp"

namespace hoct {

ScalarGraph PlMesh::graph() const {
  std::vector<GraphEdge> edges;
  edges.reserve(triangles.size() * 3);
  for (const auto &t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int64_t a = t[k], b = t[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  return ScalarGraph(values, edges);
}

MeshInput to_mesh_input(const PlMesh &pl) {
  MeshInput m;
  m.points.assign(pl.points.begin(), pl.points.end());
  m.values.assign(pl.values.begin(), pl.values.end());
  if (pl.reference != 0)
    for (double &v : m.values)
      v += pl.reference;
  m.cell_nodes.reserve(pl.triangles.size() * 3);
  for (const auto &t : pl.triangles)
    m.add_cell(1, t.data());
  return m;
}

namespace {

PlMesh split_nodal_cells(const MeshInput &in) {
  PlMesh m;
  m.points.assign(in.points.begin(), in.points.end());
  m.values.assign(in.values.begin(), in.values.end());
  m.source_cell.assign(in.points.size(), -1);
  m.source_uv.assign(in.points.size(), {0.0, 0.0});
  for (std::size_t c = 0; c < in.num_cells(); ++c) {
    const int d = in.cell_degree[c];
    const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
    if (in.kind(c) == CellKind::LagrangeQuadrilateral) {
      // The tensor grid's d^2 squares, each cut along its (i, j)-(i+1, j+1) diagonal.
      auto at = [&](int i, int j) { return nodes[i + (d + 1) * j]; };
      for (int j = 0; j <= d; ++j)
        for (int i = 0; i <= d; ++i)
          if (m.source_cell[at(i, j)] < 0) {
            m.source_cell[at(i, j)] = static_cast<int64_t>(c);
            m.source_uv[at(i, j)] = {static_cast<double>(i) / d, static_cast<double>(j) / d};
          }
      for (int j = 0; j < d; ++j)
        for (int i = 0; i < d; ++i) {
          m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
      continue;
    }
    for (int i = 0; i < lattice_size(d); ++i) {
      if (m.source_cell[nodes[i]] >= 0)
        continue;
      const auto p = lattice_point(d, i);
      m.source_cell[nodes[i]] = static_cast<int64_t>(c);
      m.source_uv[nodes[i]] = {static_cast<double>(p[0]) / d, static_cast<double>(p[1]) / d};
    }
    for (int b = 0; b < d; ++b)
      for (int a = 0; a + b < d; ++a) {
        m.triangles.push_back({nodes[lattice_index(d, a, b)], nodes[lattice_index(d, a + 1, b)],
                               nodes[lattice_index(d, a, b + 1)]});
        if (a + b + 1 < d)
          m.triangles.push_back({nodes[lattice_index(d, a + 1, b)],
                                 nodes[lattice_index(d, a + 1, b + 1)],
                                 nodes[lattice_index(d, a, b + 1)]});
      }
  }
  return m;
}

// Points no cell uses left out (they are no part of the surface: as isolated vertices they
// would be extrema of a component of their own), the others renumbered in their order.
void drop_unused_points(PlMesh &m) {
  const std::size_t n = m.points.size();
  std::vector<int64_t> to(n, -1);
  int64_t used = 0;
  for (std::size_t p = 0; p < n; ++p)
    if (m.source_cell[p] >= 0)
      to[p] = used++;
  if (used == static_cast<int64_t>(n))
    return;
  for (std::size_t p = 0; p < n; ++p)
    if (to[p] >= 0) {
      m.points[to[p]] = m.points[p];
      m.values[to[p]] = m.values[p];
      m.source_cell[to[p]] = m.source_cell[p];
      m.source_uv[to[p]] = m.source_uv[p];
    }
  m.points.resize(used);
  m.values.resize(used);
  m.source_cell.resize(used);
  m.source_uv.resize(used);
  for (auto &t : m.triangles)
    for (int64_t &v : t)
      v = to[v];
}

} // namespace

bool nodal_lagrange_cells(const MeshInput &in) {
  for (std::size_t c = 0; c < in.num_cells(); ++c)
    if (in.kind(c) != CellKind::LagrangeTriangle && in.kind(c) != CellKind::LagrangeQuadrilateral)
      return false;
  return true;
}

PlMesh split_lagrange_cells(const MeshInput &in, bool keep_unused_points) {
  PlMesh m;
  if (nodal_lagrange_cells(in)) {
    m = split_nodal_cells(in);
  } else {
    // Bezier cells through their values at the nodes' places, serendipity cells with their
    // interior nodes interpolated (mesh/cell_split); the build reported any inconsistency.
    ProblemLog ignored;
    m = split_nodal_cells(nodal_cells(in, ignored));
  }
  if (!keep_unused_points)
    drop_unused_points(m);
  return m;
}

} // namespace hoct
