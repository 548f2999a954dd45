// Topology::cut_open: the topology of a surface cut open along some interior edges, derived from
// the uncut one (docs/ALGORITHM.md §7). Building it from the cut corners would sort every edge
// again; here each edge keeps its place, a cut edge becoming two, and only each vertex's few
// edges are put back in (lo, hi) order.
#include "mesh/topology.hpp"

#include "util/page_pool.hpp"

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

Topology Topology::cut_open(std::span<const int64_t> first,
                            std::span<const std::pair<int64_t, int64_t>> split_corners,
                            std::span<const uint8_t> is_cut,
                            std::vector<int64_t> *edge_origin) const {
  const int64_t nc = num_cells(), ne = num_edges(), nv0 = num_vertices();
  const int64_t nv = first[nv0];
  const auto split = [&](int64_t v) { return first[v + 1] - first[v] > 1; };
  Topology t;

  // Vertices: a vertex with one copy keeps its lowest cell; a split one's copies get theirs from
  // the split corners (ascending, so the first corner seen is the lowest cell's).
  t.vertex_point_.resize(static_cast<std::size_t>(nv));
  std::iota(t.vertex_point_.begin(), t.vertex_point_.end(), int64_t{0});
  t.vertex_cell_.resize(static_cast<std::size_t>(nv));
  t.vertex_corner_.resize(static_cast<std::size_t>(nv));
  for (int64_t v = 0; v < nv0; ++v) {
    const bool whole = !split(v);
    for (int64_t i = first[v]; i < first[v + 1]; ++i) {
      t.vertex_cell_[i] = whole ? vertex_cell_[v] : -1;
      t.vertex_corner_[i] = whole ? vertex_corner_[v] : int8_t{0};
    }
  }
  // The large arrays are written whole: their pages are mapped in one call each.
  const auto populate = [](auto &array) {
    populate_for_write(array.data(), array.size() * sizeof(array[0]));
  };
  t.cell_vertices_.resize(static_cast<std::size_t>(nc));
  populate(t.cell_vertices_);
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k)
      t.cell_vertices_[c][k] = first[cell_vertices_[c][k]];
  for (const auto &[corner, v] : split_corners) {
    const int64_t c = corner / 3;
    const int k = static_cast<int>(corner % 3);
    t.cell_vertices_[c][k] = v;
    if (t.vertex_cell_[v] < 0) {
      t.vertex_cell_[v] = c;
      t.vertex_corner_[v] = static_cast<int8_t>(k);
    }
  }

  // The edges: this topology's in order, each cut one twice. The copies keep the originals'
  // order, so an edge keeps its place (shifted by the cut edges before it) unless its lower end is
  // split or it is cut: then the edges of its lower end are sorted again among themselves.
  int64_t cut_count = 0;
  for (int64_t e = 0; e < ne; ++e)
    cut_count += is_cut[e] != 0;
  const int64_t ne2 = ne + cut_count;
  t.edge_vertices_.resize(static_cast<std::size_t>(ne2));
  t.edge_cell_offset_.resize(static_cast<std::size_t>(ne2) + 1);
  t.edge_cells_.resize(edge_cells_.size()); // a cut edge's two cells go one to each copy
  populate(t.edge_vertices_);
  populate(t.edge_cell_offset_);
  populate(t.edge_cells_);
  if (edge_origin)
    edge_origin->resize(static_cast<std::size_t>(ne2));
  UninitializedVector<int64_t> renamed(static_cast<std::size_t>(ne)); // side 0's copy if cut
  std::vector<std::pair<int64_t, int64_t>> second;                    // (cut edge, side 1's copy)
  std::vector<int64_t> boundary_ends;
  int64_t next = 0, at = 0;
  const auto emit = [&](int64_t lo, int64_t hi, int64_t e, int side) {
    t.edge_vertices_[next] = {lo, hi};
    t.edge_cell_offset_[next] = at;
    const int64_t *cells = edge_cells_begin(e);
    const int count = edge_cell_count(e);
    if (side < 0)
      for (int i = 0; i < count; ++i)
        t.edge_cells_[at++] = cells[i];
    else
      t.edge_cells_[at++] = cells[side];
    if (side < 0 || side == 0)
      renamed[e] = next;
    else
      second.push_back({e, next});
    if (edge_origin)
      (*edge_origin)[next] = e;
    if (count == 1 || side >= 0) {
      ++t.boundary_edges_;
      boundary_ends.insert(boundary_ends.end(), {lo, hi});
    }
    ++next;
  };
  // The ends of edge e in cell c of the cut.
  const auto ends_in = [&](int64_t c, int64_t e) {
    const int k = local_edge(c, e);
    const int64_t a = t.cell_vertices_[c][k], b = t.cell_vertices_[c][(k + 1) % 3];
    return std::array<int64_t, 2>{std::min(a, b), std::max(a, b)};
  };
  std::vector<CutEdge> run;
  for (int64_t e = 0; e < ne;) {
    const int64_t lo = edge_vertices_[e][0];
    int64_t end = e;
    bool cut_here = false;
    for (; end < ne && edge_vertices_[end][0] == lo; ++end)
      cut_here = cut_here || is_cut[end];
    if (!split(lo) && !cut_here) {
      for (; e < end; ++e) {
        const int64_t hi = edge_vertices_[e][1];
        emit(first[lo], split(hi) ? ends_in(edge_cells_begin(e)[0], e)[1] : first[hi], e, -1);
      }
      continue;
    }
    run.clear();
    for (; e < end; ++e) {
      const int64_t *cells = edge_cells_begin(e);
      if (!is_cut[e]) {
        const auto ends = ends_in(cells[0], e);
        run.push_back({ends[0], ends[1], e, -1});
        continue;
      }
      for (int side = 0; side < 2; ++side) {
        const auto ends = ends_in(cells[side], e);
        run.push_back({ends[0], ends[1], e, side});
      }
    }
    std::sort(run.begin(), run.end());
    for (const CutEdge &x : run)
      emit(x.lo, x.hi, x.origin, x.side);
  }
  t.edge_cell_offset_[ne2] = at;
  if (next != ne2 || at != static_cast<int64_t>(edge_cells_.size()))
    throw std::logic_error("Topology::cut_open: a cut edge is not interior");

  // The cells' edges: renamed, the second cell of each cut edge to its own copy. Orientation is
  // this topology's: the copies keep the originals' order, so only the cells at split vertices
  // could see an edge reversed, and they are checked.
  t.cell_edges_.resize(static_cast<std::size_t>(nc));
  populate(t.cell_edges_);
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k)
      t.cell_edges_[c][k] = renamed[cell_edges_[c][k]];
  for (const auto &[e, copy] : second) {
    const int64_t c = edge_cells_begin(e)[1];
    t.cell_edges_[c][local_edge(c, e)] = copy;
  }
  t.cell_edge_reversed_.resize(static_cast<std::size_t>(nc));
  std::copy(cell_edge_reversed_.begin(), cell_edge_reversed_.end(), t.cell_edge_reversed_.begin());
  for (const auto &[corner, v] : split_corners) {
    const int64_t c = corner / 3;
    for (int k = 0; k < 3; ++k)
      if ((t.cell_vertices_[c][k] != t.edge_vertices_[t.cell_edges_[c][k]][0]) !=
          t.edge_reversed(c, k))
        throw std::logic_error("Topology::cut_open: the copies' numbering reverses an edge");
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
  const std::vector<int64_t> &ends = boundary_ends;
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
