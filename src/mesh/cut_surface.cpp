#include "mesh/cut_surface.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <numeric>
#include <string>

namespace hoct {
namespace {

// The corner of cell c at vertex v.
int corner_of(const Topology &t, int64_t c, int64_t v) {
  const auto &cv = t.cell_vertices(c);
  return cv[0] == v ? 0 : (cv[1] == v ? 1 : 2);
}

int64_t find(std::vector<int64_t> &parent, int64_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

} // namespace

std::vector<int64_t> cut_graph_edges(const Topology &t) {
  const int64_t nc = t.num_cells(), ne = t.num_edges(), nv = t.num_vertices();
  // A spanning tree of the dual graph, by breadth-first search from each component's first cell.
  std::vector<uint8_t> dual_tree(static_cast<std::size_t>(ne), 0), seen(nc, 0);
  std::vector<int64_t> queue;
  queue.reserve(static_cast<std::size_t>(nc));
  for (int64_t root = 0; root < nc; ++root) {
    if (seen[root])
      continue;
    seen[root] = 1;
    queue.clear();
    queue.push_back(root);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int64_t c = queue[q];
      for (int k = 0; k < 3; ++k) {
        const int64_t d = t.neighbor(c, k);
        if (d >= 0 && !seen[d]) {
          seen[d] = 1;
          dual_tree[t.cell_edge(c, k)] = 1;
          queue.push_back(d);
        }
      }
    }
  }
  // The cut: interior edges off the dual tree. Dangling ones (an end of no other cut or boundary
  // edge) are pruned until none is left: uncutting them keeps each component a disk.
  std::vector<uint8_t> cut(static_cast<std::size_t>(ne), 0);
  std::vector<int32_t> degree(static_cast<std::size_t>(nv), 0);
  std::vector<int64_t> offset(static_cast<std::size_t>(nv) + 1, 0);
  for (int64_t e = 0; e < ne; ++e) {
    cut[e] = t.edge_cell_count(e) == 2 && !dual_tree[e];
    if (cut[e] || t.is_boundary_edge(e))
      for (int64_t v : t.edge_vertices(e))
        ++degree[v];
    if (cut[e])
      for (int64_t v : t.edge_vertices(e))
        ++offset[v + 1];
  }
  for (int64_t v = 0; v < nv; ++v)
    offset[v + 1] += offset[v];
  std::vector<int64_t> incident(static_cast<std::size_t>(offset[nv]));
  {
    std::vector<int64_t> fill(offset.begin(), offset.end() - 1);
    for (int64_t e = 0; e < ne; ++e)
      if (cut[e])
        for (int64_t v : t.edge_vertices(e))
          incident[fill[v]++] = e;
  }
  std::vector<int64_t> leaves;
  for (int64_t v = 0; v < nv; ++v)
    if (degree[v] == 1)
      leaves.push_back(v);
  while (!leaves.empty()) {
    const int64_t v = leaves.back();
    leaves.pop_back();
    if (degree[v] != 1)
      continue;
    for (int64_t k = offset[v]; k < offset[v + 1]; ++k) {
      const int64_t e = incident[k];
      if (!cut[e])
        continue;
      cut[e] = 0;
      for (int64_t w : t.edge_vertices(e))
        if (--degree[w] == 1)
          leaves.push_back(w);
      break;
    }
  }
  std::vector<int64_t> edges;
  for (int64_t e = 0; e < ne; ++e)
    if (cut[e])
      edges.push_back(e);
  return edges;
}

CornerCut cut_corners(const Topology &t, std::span<const int64_t> cut_edges) {
  const int64_t nc = t.num_cells(), nv = t.num_vertices();
  std::vector<uint8_t> is_cut(static_cast<std::size_t>(t.num_edges()), 0), on_cut(nv, 0);
  for (int64_t e : cut_edges) {
    is_cut[e] = 1;
    for (int64_t v : t.edge_vertices(e))
      on_cut[v] = 1;
  }
  // The cells' corners at vertices on the cut, joined across the uncut edges: each set is a
  // wedge of cells between two cut (or boundary) edges, and gets its own copy of the vertex.
  std::vector<int64_t> parent(static_cast<std::size_t>(3 * nc));
  std::iota(parent.begin(), parent.end(), int64_t{0});
  for (int64_t e = 0; e < t.num_edges(); ++e) {
    if (is_cut[e] || t.edge_cell_count(e) != 2)
      continue;
    const int64_t c1 = t.edge_cells_begin(e)[0], c2 = t.edge_cells_begin(e)[1];
    for (int64_t v : t.edge_vertices(e))
      if (on_cut[v]) {
        const int64_t a = find(parent, 3 * c1 + corner_of(t, c1, v));
        const int64_t b = find(parent, 3 * c2 + corner_of(t, c2, v));
        parent[std::max(a, b)] = std::min(a, b);
      }
  }
  // Copies per vertex: one per wedge (the roots are each wedge's lowest corner).
  std::vector<int64_t> wedges(static_cast<std::size_t>(nv), 1);
  for (int64_t v = 0; v < nv; ++v)
    if (on_cut[v])
      wedges[v] = 0;
  for (int64_t k = 0; k < 3 * nc; ++k) {
    const int64_t v = t.cell_vertices(k / 3)[k % 3];
    if (on_cut[v] && find(parent, k) == k)
      ++wedges[v];
  }
  std::vector<int64_t> first(static_cast<std::size_t>(nv) + 1, 0);
  for (int64_t v = 0; v < nv; ++v)
    first[v + 1] = first[v] + wedges[v];
  CornerCut out;
  out.vertex_origin.resize(static_cast<std::size_t>(first[nv]));
  for (int64_t v = 0; v < nv; ++v)
    for (int64_t i = first[v]; i < first[v + 1]; ++i)
      out.vertex_origin[i] = v;
  // Each wedge's copy: in the order of the wedges' lowest corners.
  std::vector<int64_t> copy_of_root(static_cast<std::size_t>(3 * nc), -1);
  std::vector<int64_t> next(first.begin(), first.end() - 1);
  out.corner_vertex.resize(static_cast<std::size_t>(3 * nc));
  for (int64_t k = 0; k < 3 * nc; ++k) {
    const int64_t v = t.cell_vertices(k / 3)[k % 3];
    int64_t id = first[v];
    if (on_cut[v]) {
      const int64_t r = find(parent, k);
      if (copy_of_root[r] < 0)
        copy_of_root[r] = next[v]++;
      id = copy_of_root[r];
    }
    out.corner_vertex[k] = id;
  }
  for (int64_t v = 0; v < nv; ++v)
    if (wedges[v] > 1) {
      for (int64_t i = first[v]; i < first[v + 1]; ++i)
        out.copies.push_back(i);
      out.group_offset.push_back(static_cast<int64_t>(out.copies.size()));
    }
  return out;
}

std::vector<std::array<int64_t, 4>> seam_vertices(const Topology &t, const CornerCut &cut,
                                                  std::span<const int64_t> cut_edges) {
  std::vector<std::array<int64_t, 4>> seams;
  seams.reserve(cut_edges.size());
  for (int64_t e : cut_edges) {
    const auto ends = t.edge_vertices(e);
    std::array<int64_t, 4> s{};
    for (int side = 0; side < 2; ++side) {
      const int64_t c = t.edge_cells_begin(e)[side];
      for (int k = 0; k < 2; ++k)
        s[2 * side + k] = cut.corner_vertex[3 * c + corner_of(t, c, ends[k])];
    }
    seams.push_back(s);
  }
  return seams;
}

CutSurface cut_open(const Mesh &mesh, std::span<const int64_t> cut_edges, int threads) {
  const Topology &t = mesh.topology;
  const int64_t nc = t.num_cells();
  std::vector<uint8_t> is_cut(static_cast<std::size_t>(t.num_edges()), 0);
  for (int64_t e : cut_edges)
    is_cut[e] = 1;
  CornerCut corner_cut = cut_corners(t, cut_edges);
  CutSurface out;
  out.vertex_origin = std::move(corner_cut.vertex_origin);
  out.group_offset = std::move(corner_cut.group_offset);
  out.copies = std::move(corner_cut.copies);
  MeshInput corners;
  corners.points.resize(out.vertex_origin.size());
  corners.cell_nodes.assign(corner_cut.corner_vertex.begin(), corner_cut.corner_vertex.end());
  corner_cut.corner_vertex = {};
  corners.cell_offsets.resize(static_cast<std::size_t>(nc) + 1);
  corners.cell_degree.assign(static_cast<std::size_t>(nc), 1);
  for (int64_t c = 0; c <= nc; ++c)
    corners.cell_offsets[c] = 3 * c; // corner k of a degree-1 cell is its node k

  ProblemLog problems;
  Topology cut = Topology::build(corners, problems, threads);
  const auto disks = [&](const Topology &x) {
    return x.components() == t.components() && x.euler_characteristic() == x.components() &&
           x.boundary_loops() == x.components();
  };
  if (problems.has_errors() || !disks(cut))
    throw Error((mesh.source.empty() ? std::string("the mesh") : mesh.source) +
                ": cutting the surface open along " + std::to_string(cut_edges.size()) +
                " edges did not give one disk per component (Euler characteristic " +
                std::to_string(cut.euler_characteristic()) + ", " +
                std::to_string(cut.boundary_loops()) + " boundary loops, " +
                std::to_string(cut.components()) + " components): an internal error");
  // Each edge of the cut mesh stands for the edge of its cells' original; the copies keep the
  // originals' order, so no edge is reversed.
  std::vector<int64_t> edge_origin(static_cast<std::size_t>(cut.num_edges()), -1);
  std::vector<std::array<int64_t, 2>> seam_of(static_cast<std::size_t>(t.num_edges()), {-1, -1});
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k) {
      const int64_t e = t.cell_edge(c, k), e2 = cut.cell_edge(c, k);
      if (cut.edge_reversed(c, k) != t.edge_reversed(c, k))
        throw Error("cutting the surface open reversed an edge: an internal error");
      edge_origin[e2] = e;
      if (is_cut[e])
        seam_of[e][seam_of[e][0] < 0 ? 0 : 1] = e2;
    }
  for (int64_t e : cut_edges)
    out.seams.push_back(seam_of[e]);

  Mesh &m = out.mesh;
  m.source = mesh.source;
  m.field_name = mesh.field_name;
  m.field_detail = mesh.field_detail;
  m.num_points = mesh.num_points;
  m.fingerprint = mesh.fingerprint;
  m.field = mesh.field.on_cut_topology(cut, edge_origin, out.vertex_origin);
  m.topology = std::move(cut);
  m.geometry = mesh.geometry;
  m.complete = true;
  m.origins = mesh.origins;
  m.input_quadrilaterals = mesh.input_quadrilaterals;
  m.input_bezier_cells = mesh.input_bezier_cells;
  m.input_cell_kinds = mesh.input_cell_kinds;
  m.build_times = mesh.build_times;
  return out;
}

} // namespace hoct
