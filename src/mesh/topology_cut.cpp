// Topology::cut_open: the topology of a surface cut open along some interior edges, derived from
// the uncut one (docs/ALGORITHM.md §7). Building it from the cut corners would sort every edge
// again; here each edge keeps its place, a cut edge becoming two, and only each vertex's few
// edges are put back in (lo, hi) order.
#include "mesh/topology.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace hoct {
namespace {

int64_t find(std::vector<int64_t> &parent, int64_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// An edge of the cut topology: its ends, the original edge and which of its cells it keeps (-1:
// both, an uncut edge; 0 or 1: the copy on that cell's side).
struct CutEdge {
  int64_t lo, hi, origin;
  int side;
  bool operator<(const CutEdge &o) const { return lo < o.lo || (lo == o.lo && hi < o.hi); }
};

} // namespace

Topology Topology::cut_open(std::span<const int64_t> corner_vertex, int64_t nv,
                            std::span<const uint8_t> is_cut) const {
  const int64_t nc = num_cells(), ne = num_edges();
  Topology t;
  t.vertex_point_.resize(static_cast<std::size_t>(nv));
  std::iota(t.vertex_point_.begin(), t.vertex_point_.end(), int64_t{0});
  t.cell_vertices_.resize(static_cast<std::size_t>(nc));
  t.vertex_cell_.resize(static_cast<std::size_t>(nv));
  std::fill(t.vertex_cell_.begin(), t.vertex_cell_.end(), int64_t{-1});
  t.vertex_corner_.resize(static_cast<std::size_t>(nv));
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k) {
      const int64_t v = corner_vertex[3 * c + k];
      t.cell_vertices_[c][k] = v;
      if (t.vertex_cell_[v] < 0) { // cells in ascending order: the first is the lowest
        t.vertex_cell_[v] = c;
        t.vertex_corner_[v] = static_cast<int8_t>(k);
      }
    }

  // The edges: this topology's in order, each cut one twice; the copies' ids keep the originals'
  // order, so only the edges sharing a lower original vertex can change places among themselves.
  std::vector<CutEdge> edges;
  edges.reserve(static_cast<std::size_t>(ne) + 64);
  const auto ends_in = [&](int64_t c, int64_t e) {
    const int k = local_edge(c, e);
    const int64_t a = corner_vertex[3 * c + k], b = corner_vertex[3 * c + (k + 1) % 3];
    return std::array<int64_t, 2>{std::min(a, b), std::max(a, b)};
  };
  for (int64_t e = 0; e < ne;) {
    const std::size_t run = edges.size();
    const int64_t lo = edge_vertices_[e][0];
    for (; e < ne && edge_vertices_[e][0] == lo; ++e) {
      const int64_t *cells = edge_cells_begin(e);
      if (!is_cut[e]) {
        const auto ends = ends_in(cells[0], e);
        edges.push_back({ends[0], ends[1], e, -1});
        continue;
      }
      for (int side = 0; side < 2; ++side) {
        const auto ends = ends_in(cells[side], e);
        edges.push_back({ends[0], ends[1], e, side});
      }
    }
    if (!std::is_sorted(edges.begin() + static_cast<std::ptrdiff_t>(run), edges.end()))
      std::sort(edges.begin() + static_cast<std::ptrdiff_t>(run), edges.end());
  }
  const int64_t ne2 = static_cast<int64_t>(edges.size());
  t.edge_vertices_.resize(static_cast<std::size_t>(ne2));
  t.edge_cell_offset_.resize(static_cast<std::size_t>(ne2) + 1);
  t.cell_edges_.resize(static_cast<std::size_t>(nc));
  int64_t incidences = 0;
  for (const CutEdge &x : edges)
    incidences += x.side < 0 ? edge_cell_count(x.origin) : 1;
  t.edge_cells_.resize(static_cast<std::size_t>(incidences));
  int64_t at = 0;
  for (int64_t e2 = 0; e2 < ne2; ++e2) {
    const CutEdge &x = edges[e2];
    t.edge_vertices_[e2] = {x.lo, x.hi};
    t.edge_cell_offset_[e2] = at;
    const int64_t *cells = edge_cells_begin(x.origin);
    const int count = edge_cell_count(x.origin);
    for (int i = 0; i < count; ++i)
      if (x.side < 0 || x.side == i) {
        t.edge_cells_[at++] = cells[i];
        t.cell_edges_[cells[i]][local_edge(cells[i], x.origin)] = e2;
      }
    if (count == 1 || x.side >= 0)
      ++t.boundary_edges_;
  }
  t.edge_cell_offset_[ne2] = at;
  t.cell_edge_reversed_.resize(static_cast<std::size_t>(nc));
  for (int64_t c = 0; c < nc; ++c) {
    uint8_t reversed = 0;
    for (int k = 0; k < 3; ++k)
      if (t.cell_vertices_[c][k] != t.edge_vertices_[t.cell_edges_[c][k]][0])
        reversed |= static_cast<uint8_t>(1u << k);
    if (reversed != cell_edge_reversed_[c])
      throw std::logic_error("Topology::cut_open: the copies' numbering reverses an edge");
    t.cell_edge_reversed_[c] = reversed;
  }

  // Components: this one's. Orientation: an orientable surface keeps its cells' parities; a
  // non-orientable one (a Moebius strip) cut into disks gets them by a walk over the cut mesh.
  t.components_ = components_;
  t.cell_parity_.resize(static_cast<std::size_t>(nc));
  if (orientable_) {
    std::copy(cell_parity_.begin(), cell_parity_.end(), t.cell_parity_.begin());
  } else {
    std::fill(t.cell_parity_.begin(), t.cell_parity_.end(), int8_t{0});
    std::vector<int64_t> queue;
    for (int64_t s = 0; s < nc; ++s) {
      if (t.cell_parity_[s] != 0)
        continue;
      t.cell_parity_[s] = 1;
      queue.assign(1, s);
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const int64_t c = queue[q];
        for (int k = 0; k < 3; ++k) {
          const int64_t n = t.neighbor(c, k);
          if (n < 0)
            continue;
          const int kn = t.local_edge(n, t.cell_edges_[c][k]);
          const bool same_dir = t.edge_reversed(c, k) == t.edge_reversed(n, kn);
          const int8_t want =
              static_cast<int8_t>(same_dir ? -t.cell_parity_[c] : t.cell_parity_[c]);
          if (t.cell_parity_[n] == 0) {
            t.cell_parity_[n] = want;
            queue.push_back(n);
          } else if (t.cell_parity_[n] != want) {
            t.orientable_ = false;
          }
        }
      }
    }
  }

  // Boundary loops: components of the boundary edges' graph, over their vertices only.
  std::vector<int64_t> ends;
  for (int64_t e2 = 0; e2 < ne2; ++e2)
    if (t.is_boundary_edge(e2))
      ends.insert(ends.end(), {t.edge_vertices_[e2][0], t.edge_vertices_[e2][1]});
  std::vector<int64_t> vertices = ends;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  const auto index = [&](int64_t v) {
    return std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin();
  };
  std::vector<int64_t> parent(vertices.size());
  std::iota(parent.begin(), parent.end(), int64_t{0});
  for (std::size_t i = 0; i < ends.size(); i += 2) {
    const int64_t a = find(parent, index(ends[i])), b = find(parent, index(ends[i + 1]));
    parent[std::max(a, b)] = std::min(a, b);
  }
  for (std::size_t i = 0; i < parent.size(); ++i)
    t.boundary_loops_ += find(parent, static_cast<int64_t>(i)) == static_cast<int64_t>(i);
  return t;
}

} // namespace hoct
