#include "mesh/topology.hpp"

#include "poly/lattice.hpp"
#include "tree/union_find.hpp"

#include <algorithm>
#include <sstream>

namespace hoct {
namespace {

struct EdgeRecord {
  int64_t lo, hi, cell;
  int local;
  bool operator<(const EdgeRecord &o) const {
    if (lo != o.lo)
      return lo < o.lo;
    if (hi != o.hi)
      return hi < o.hi;
    if (cell != o.cell)
      return cell < o.cell;
    return local < o.local;
  }
};

} // namespace

int64_t Topology::neighbor(int64_t c, int k) const {
  const int64_t e = cell_edges_[c][k];
  if (edge_cell_count(e) != 2)
    return -1;
  const int64_t *cells = edge_cells_begin(e);
  return cells[0] == c ? cells[1] : cells[0];
}

Topology Topology::build(const MeshInput &in, ProblemLog &problems) {
  Topology t;
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  // Vertices: the distinct corner points, numbered in order of first appearance by point index.
  std::vector<int64_t> point_vertex(in.num_points(), -1);
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k)
      point_vertex[in.cell_nodes[in.cell_offsets[c] + corner_index(in.cell_degree[c], k)]] = 0;
  for (std::size_t p = 0; p < point_vertex.size(); ++p)
    if (point_vertex[p] == 0) {
      point_vertex[p] = static_cast<int64_t>(t.vertex_point_.size());
      t.vertex_point_.push_back(static_cast<int64_t>(p));
    }
  t.cell_vertices_.resize(nc);
  for (int64_t c = 0; c < nc; ++c) {
    const int d = in.cell_degree[c];
    const int64_t base = in.cell_offsets[c];
    const int64_t corner[3] = {in.cell_nodes[base + corner_index(d, 0)],
                               in.cell_nodes[base + corner_index(d, 1)],
                               in.cell_nodes[base + corner_index(d, 2)]};
    for (int k = 0; k < 3; ++k)
      t.cell_vertices_[c][k] = point_vertex[corner[k]];
    const auto &v = t.cell_vertices_[c];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      std::ostringstream m;
      m << "cell " << c << " uses the same corner point twice (points " << corner[0] << ", "
        << corner[1] << ", " << corner[2] << ")";
      problems.add("degenerate cell (repeated corner)", Severity::Error, m.str());
    }
  }

  t.vertex_cell_.assign(t.vertex_point_.size(), -1);
  t.vertex_corner_.assign(t.vertex_point_.size(), 0);
  for (int64_t c = nc - 1; c >= 0; --c)
    for (int k = 0; k < 3; ++k) {
      t.vertex_cell_[t.cell_vertices_[c][k]] = c;
      t.vertex_corner_[t.cell_vertices_[c][k]] = static_cast<int8_t>(k);
    }

  // Edges: (lo, hi, cell, local) records in that order, bucketed by lo (a counting sort) and
  // each bucket (a vertex's few edges) sorted.
  const int64_t nv = static_cast<int64_t>(t.vertex_point_.size());
  std::vector<int64_t> bucket(nv + 1, 0);
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k)
      ++bucket[std::min(t.cell_vertices_[c][k], t.cell_vertices_[c][(k + 1) % 3]) + 1];
  for (int64_t v = 0; v < nv; ++v)
    bucket[v + 1] += bucket[v];
  std::vector<EdgeRecord> rec(static_cast<std::size_t>(3 * nc));
  {
    std::vector<int64_t> fill(bucket.begin(), bucket.end() - 1);
    for (int64_t c = 0; c < nc; ++c)
      for (int k = 0; k < 3; ++k) {
        const int64_t a = t.cell_vertices_[c][k], b = t.cell_vertices_[c][(k + 1) % 3];
        rec[fill[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), c, k};
      }
  }
  for (int64_t v = 0; v < nv; ++v)
    std::sort(rec.begin() + bucket[v], rec.begin() + bucket[v + 1]);
  t.cell_edges_.assign(nc, {-1, -1, -1});
  t.cell_edge_reversed_.assign(nc, 0);
  t.edge_cell_offset_.push_back(0);
  for (std::size_t i = 0; i < rec.size();) {
    std::size_t j = i;
    while (j < rec.size() && rec[j].lo == rec[i].lo && rec[j].hi == rec[i].hi)
      ++j;
    const int64_t e = static_cast<int64_t>(t.edge_vertices_.size());
    t.edge_vertices_.push_back({rec[i].lo, rec[i].hi});
    for (std::size_t r = i; r < j; ++r) {
      const auto &x = rec[r];
      t.cell_edges_[x.cell][x.local] = e;
      if (t.cell_vertices_[x.cell][x.local] != x.lo)
        t.cell_edge_reversed_[x.cell] |= static_cast<uint8_t>(1u << x.local);
      t.edge_cells_.push_back(x.cell);
    }
    t.edge_cell_offset_.push_back(static_cast<int64_t>(t.edge_cells_.size()));
    const std::size_t count = j - i;
    if (count == 1)
      ++t.boundary_edges_;
    if (count > 2) {
      std::ostringstream m;
      m << "edge between points " << t.vertex_point_[rec[i].lo] << " and "
        << t.vertex_point_[rec[i].hi] << " is shared by " << count << " cells (";
      for (std::size_t r = i; r < j; ++r)
        m << (r > i ? ", " : "") << rec[r].cell;
      m << ")";
      problems.add("non-manifold edge", Severity::Error, m.str());
    }
    if (count == 2 && rec[i].cell == rec[i + 1].cell) {
      problems.add("degenerate cell (repeated edge)", Severity::Error,
                   "cell " + std::to_string(rec[i].cell) + " uses the same edge twice");
    }
    i = j;
  }

  // Components and a consistent orientation, by a breadth-first walk over manifold edges.
  t.cell_parity_.assign(nc, 0);
  std::vector<int64_t> queue;
  int64_t orientation_conflicts = 0;
  for (int64_t s = 0; s < nc; ++s) {
    if (t.cell_parity_[s] != 0)
      continue;
    ++t.components_;
    t.cell_parity_[s] = 1;
    queue.assign(1, s);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int64_t c = queue[q];
      for (int k = 0; k < 3; ++k) {
        const int64_t n = t.neighbor(c, k);
        if (n < 0 || n == c)
          continue;
        int kn = 0;
        while (kn < 3 && t.cell_edges_[n][kn] != t.cell_edges_[c][k])
          ++kn;
        // Consistently oriented neighbours run the shared edge in opposite directions.
        const bool same_dir = t.edge_reversed(c, k) == t.edge_reversed(n, kn);
        const int8_t want = static_cast<int8_t>(same_dir ? -t.cell_parity_[c] : t.cell_parity_[c]);
        if (t.cell_parity_[n] == 0) {
          t.cell_parity_[n] = want;
          queue.push_back(n);
        } else if (t.cell_parity_[n] != want) {
          ++orientation_conflicts;
        }
      }
    }
  }
  if (orientation_conflicts > 0) {
    t.orientable_ = false;
    problems.add("non-orientable surface", Severity::Warning,
                 "the cells cannot be oriented consistently (" +
                     std::to_string(orientation_conflicts / 2) + " conflicting edges)");
  }

  // Boundary loops: components of the boundary-edge graph; every boundary vertex of a manifold
  // has exactly two boundary edges.
  std::vector<int> boundary_degree(t.vertex_point_.size(), 0);
  UnionFind uf(t.vertex_point_.size());
  for (int64_t e = 0; e < t.num_edges(); ++e)
    if (t.is_boundary_edge(e)) {
      ++boundary_degree[t.edge_vertices_[e][0]];
      ++boundary_degree[t.edge_vertices_[e][1]];
      uf.unite(t.edge_vertices_[e][0], t.edge_vertices_[e][1]);
    }
  for (std::size_t v = 0; v < boundary_degree.size(); ++v) {
    if (boundary_degree[v] == 0)
      continue;
    if (uf.find(static_cast<int64_t>(v)) == static_cast<int64_t>(v))
      ++t.boundary_loops_;
    if (boundary_degree[v] != 2)
      problems.add("non-manifold vertex", Severity::Error,
                   "point " + std::to_string(t.vertex_point_[v]) + " touches " +
                       std::to_string(boundary_degree[v]) +
                       " boundary edges (a pinch: two boundary loops meet there)");
  }

  // Vertices whose cells form more than one fan (pinched at an interior vertex), found by
  // counting, per vertex, the cells and the manifold edges that join them around it.
  std::vector<int64_t> vcells(t.vertex_point_.size(), 0), vlinks(t.vertex_point_.size(), 0);
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k)
      ++vcells[t.cell_vertices_[c][k]];
  for (int64_t e = 0; e < t.num_edges(); ++e)
    if (t.edge_cell_count(e) == 2) {
      ++vlinks[t.edge_vertices_[e][0]];
      ++vlinks[t.edge_vertices_[e][1]];
    }
  for (std::size_t v = 0; v < vcells.size(); ++v) {
    // One fan: a cycle (links == cells, no boundary) or a path (links == cells - 1).
    const bool ok = boundary_degree[v] == 0
                        ? vlinks[v] == vcells[v]
                        : (boundary_degree[v] == 2 && vlinks[v] == vcells[v] - 1);
    if (!ok && boundary_degree[v] <= 2 && t.num_edges() > 0 &&
        problems.count("non-manifold edge") == 0)
      problems.add("non-manifold vertex", Severity::Error,
                   "point " + std::to_string(t.vertex_point_[v]) +
                       ": its cells form more than one fan (two parts of the surface touch at a "
                       "single vertex)");
  }
  return t;
}

} // namespace hoct
