#include "mesh/topology.hpp"

#include "poly/lattice.hpp"
#include "tree/union_find.hpp"

#include <algorithm>
#include <sstream>

namespace hoct {
namespace {

// A cell's edge, in the bucket of its lower vertex: the higher vertex, then 3 cell + local edge
// (the order of the records in a bucket: by higher vertex, then cell, then local edge).
struct EdgeRecord {
  int64_t hi, cell_local;
  bool operator<(const EdgeRecord &o) const {
    return hi < o.hi || (hi == o.hi && cell_local < o.cell_local);
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
        rec[fill[std::min(a, b)]++] = {std::max(a, b), 3 * c + k};
      }
  }
  int64_t edges = 0;
  for (int64_t v = 0; v < nv; ++v) {
    std::sort(rec.begin() + bucket[v], rec.begin() + bucket[v + 1]);
    for (int64_t i = bucket[v]; i < bucket[v + 1]; ++i)
      edges += i == bucket[v] || rec[i].hi != rec[i - 1].hi;
  }
  t.cell_edges_.assign(nc, {-1, -1, -1});
  t.cell_edge_reversed_.assign(nc, 0);
  t.edge_vertices_.reserve(static_cast<std::size_t>(edges));
  t.edge_cells_.reserve(rec.size());
  t.edge_cell_offset_.reserve(static_cast<std::size_t>(edges) + 1);
  t.edge_cell_offset_.push_back(0);
  // The local edge of each (edge, cell) incidence, in edge_cells_ order: the orientation walk
  // below finds a neighbour's side of the shared edge there, not by searching the neighbour.
  std::vector<int8_t> incidence_local(rec.size());
  for (int64_t lo = 0; lo < nv; ++lo)
    for (int64_t i = bucket[lo]; i < bucket[lo + 1];) {
      int64_t j = i;
      while (j < bucket[lo + 1] && rec[j].hi == rec[i].hi)
        ++j;
      const int64_t hi = rec[i].hi;
      const int64_t e = static_cast<int64_t>(t.edge_vertices_.size());
      t.edge_vertices_.push_back({lo, hi});
      for (int64_t r = i; r < j; ++r) {
        const int64_t cell = rec[r].cell_local / 3;
        const int local = static_cast<int>(rec[r].cell_local % 3);
        t.cell_edges_[cell][local] = e;
        if (t.cell_vertices_[cell][local] != lo)
          t.cell_edge_reversed_[cell] |= static_cast<uint8_t>(1u << local);
        incidence_local[t.edge_cells_.size()] = static_cast<int8_t>(local);
        t.edge_cells_.push_back(cell);
      }
      t.edge_cell_offset_.push_back(static_cast<int64_t>(t.edge_cells_.size()));
      const int64_t count = j - i;
      if (count == 1)
        ++t.boundary_edges_;
      if (count > 2) {
        std::ostringstream m;
        m << "edge between points " << t.vertex_point_[lo] << " and " << t.vertex_point_[hi]
          << " is shared by " << count << " cells (";
        for (int64_t r = i; r < j; ++r)
          m << (r > i ? ", " : "") << rec[r].cell_local / 3;
        m << ")";
        problems.add("non-manifold edge", Severity::Error, m.str());
      }
      if (count == 2 && rec[i].cell_local / 3 == rec[i + 1].cell_local / 3) {
        problems.add("degenerate cell (repeated edge)", Severity::Error,
                     "cell " + std::to_string(rec[i].cell_local / 3) + " uses the same edge twice");
      }
      i = j;
    }
  std::vector<EdgeRecord>().swap(rec);

  // Components and a consistent orientation. Most inputs are consistently oriented already (the
  // two cells of every manifold edge run it in opposite directions): then every cell keeps
  // parity +1, as the walk below would give it, and only the components remain to count, by
  // disjoint sets over the edges in edge order (no walk from cell to cell through memory).
  bool consistent = true;
  for (int64_t e = 0; e < t.num_edges() && consistent; ++e) {
    const int64_t at = t.edge_cell_offset_[e];
    if (t.edge_cell_offset_[e + 1] - at != 2)
      continue;
    const int64_t c0 = t.edge_cells_[at], c1 = t.edge_cells_[at + 1];
    consistent = c0 == c1 || t.edge_reversed(c0, incidence_local[at]) !=
                                 t.edge_reversed(c1, incidence_local[at + 1]);
  }
  if (consistent) {
    t.cell_parity_.assign(nc, 1);
    UnionFind cells(static_cast<std::size_t>(nc));
    for (int64_t e = 0; e < t.num_edges(); ++e) {
      const int64_t at = t.edge_cell_offset_[e];
      if (t.edge_cell_offset_[e + 1] - at == 2)
        cells.unite(t.edge_cells_[at], t.edge_cells_[at + 1]);
    }
    for (int64_t c = 0; c < nc; ++c)
      t.components_ += cells.find(c) == c;
  }
  // Otherwise a breadth-first walk over manifold edges gives each cell its parity.
  if (!consistent)
    t.cell_parity_.assign(nc, 0);
  std::vector<int64_t> queue;
  int64_t orientation_conflicts = 0;
  for (int64_t s = 0; s < nc && !consistent; ++s) {
    if (t.cell_parity_[s] != 0)
      continue;
    ++t.components_;
    t.cell_parity_[s] = 1;
    queue.assign(1, s);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int64_t c = queue[q];
      for (int k = 0; k < 3; ++k) {
        const int64_t e = t.cell_edges_[c][k];
        if (t.edge_cell_count(e) != 2)
          continue;
        const int64_t at = t.edge_cell_offset_[e] + (t.edge_cells_[t.edge_cell_offset_[e]] == c);
        const int64_t n = t.edge_cells_[at];
        if (n == c)
          continue;
        const int kn = incidence_local[at];
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
