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
  // A spanning forest of the dual graph (cells across interior edges), by union-find over the
  // interior edges in edge order: the edges it does not take are the cut before pruning.
  std::vector<int64_t> parent(static_cast<std::size_t>(nc));
  std::iota(parent.begin(), parent.end(), int64_t{0});
  std::vector<uint8_t> cut(static_cast<std::size_t>(ne), 0);
  // Per vertex: its cut and boundary edges, its cut edges, and the exclusive or of their ids (so
  // a vertex left with one cut edge knows which, without an incidence list).
  std::vector<int32_t> degree(static_cast<std::size_t>(nv), 0), cut_degree(nv, 0);
  std::vector<int64_t> cut_xor(static_cast<std::size_t>(nv), 0);
  for (int64_t e = 0; e < ne; ++e) {
    const int cells = t.edge_cell_count(e);
    if (cells == 2) {
      const int64_t a = find(parent, t.edge_cells_begin(e)[0]);
      const int64_t b = find(parent, t.edge_cells_begin(e)[1]);
      if (a != b)
        parent[std::max(a, b)] = std::min(a, b);
      else
        cut[e] = 1;
    }
    if (cut[e] || cells == 1)
      for (int64_t v : t.edge_vertices(e)) {
        ++degree[v];
        if (cut[e]) {
          ++cut_degree[v];
          cut_xor[v] ^= e;
        }
      }
  }
  parent = {};
  // Dangling cut edges (an end of no other cut or boundary edge) are pruned until none is left:
  // uncutting them keeps each component a disk.
  std::vector<int64_t> leaves;
  const auto dangling = [&](int64_t v) { return degree[v] == 1 && cut_degree[v] == 1; };
  for (int64_t v = 0; v < nv; ++v)
    if (dangling(v))
      leaves.push_back(v);
  while (!leaves.empty()) {
    const int64_t v = leaves.back();
    leaves.pop_back();
    if (!dangling(v))
      continue;
    const int64_t e = cut_xor[v];
    cut[e] = 0;
    for (int64_t w : t.edge_vertices(e)) {
      --degree[w];
      --cut_degree[w];
      cut_xor[w] ^= e;
      if (dangling(w))
        leaves.push_back(w);
    }
  }
  std::vector<int64_t> edges;
  for (int64_t e = 0; e < ne; ++e)
    if (cut[e])
      edges.push_back(e);
  return edges;
}

namespace {

// The cells around vertex v in order (a cycle inside, a path from boundary edge to boundary edge
// on the boundary), each with the edge crossed from it to the next (-1 after the last of a path).
struct Fan {
  std::vector<int64_t> cells, crossed;
  bool closed = false;
};

void walk_fan(const Topology &t, int64_t v, Fan &fan) {
  // From cell c, entered across `entered`, the other edge at v: its local index.
  const auto exit_edge = [&](int64_t c, int64_t entered, bool forward) {
    const int j = corner_of(t, c, v);
    const int ahead = j, behind = (j + 2) % 3; // local edges j -> j+1 and j+2 -> j
    if (entered < 0)
      return forward ? ahead : behind;
    return t.cell_edge(c, ahead) == entered ? behind : ahead;
  };
  const int64_t start = t.vertex_cell(v);
  fan.cells.assign(1, start);
  fan.crossed.clear();
  fan.closed = false;
  int64_t c = start, entered = -1;
  for (;;) {
    const int k = exit_edge(c, entered, true);
    const int64_t d = t.neighbor(c, k);
    if (d < 0)
      break;
    fan.crossed.push_back(t.cell_edge(c, k));
    if (d == start) {
      fan.closed = true;
      return;
    }
    entered = t.cell_edge(c, k);
    fan.cells.push_back(c = d);
  }
  fan.crossed.push_back(-1);
  // On the boundary: the cells behind the start, walked back to the other boundary edge.
  std::vector<int64_t> back_cells, back_crossed;
  c = start;
  entered = -1;
  for (;;) {
    const int k = exit_edge(c, entered, false);
    const int64_t d = t.neighbor(c, k);
    if (d < 0)
      break;
    back_crossed.push_back(t.cell_edge(c, k));
    entered = t.cell_edge(c, k);
    back_cells.push_back(c = d);
  }
  std::reverse(back_cells.begin(), back_cells.end());
  std::reverse(back_crossed.begin(), back_crossed.end());
  back_cells.insert(back_cells.end(), fan.cells.begin(), fan.cells.end());
  back_crossed.insert(back_crossed.end(), fan.crossed.begin(), fan.crossed.end());
  fan.cells = std::move(back_cells);
  fan.crossed = std::move(back_crossed);
}

// The wedges at vertices that may hold several fans (split_vertices): corners at such a vertex
// are in one wedge when joined across its uncut interior edges (union-find over the corners).
class SplitFans {
public:
  SplitFans(const Topology &t, std::span<const uint8_t> is_cut, std::span<const int64_t> split)
      : split_(split.begin(), split.end()) {
    if (split_.empty())
      return;
    for (int64_t c = 0; c < t.num_cells(); ++c)
      for (int k = 0; k < 3; ++k)
        if (holds(t.cell_vertices(c)[k]))
          corners_.push_back({t.cell_vertices(c)[k], 3 * c + k});
    std::sort(corners_.begin(), corners_.end());
    parent_.resize(corners_.size());
    std::iota(parent_.begin(), parent_.end(), int64_t{0});
    for (int64_t e = 0; e < t.num_edges(); ++e) {
      if (is_cut[e] || t.edge_cell_count(e) != 2)
        continue;
      const int64_t c0 = t.edge_cells_begin(e)[0], c1 = t.edge_cells_begin(e)[1];
      for (int64_t w : t.edge_vertices(e))
        if (holds(w)) {
          const int64_t a = find(parent_, index(w, 3 * c0 + corner_of(t, c0, w)));
          const int64_t b = find(parent_, index(w, 3 * c1 + corner_of(t, c1, w)));
          parent_[std::max(a, b)] = std::min(a, b);
        }
    }
  }

  bool holds(int64_t v) const { return std::binary_search(split_.begin(), split_.end(), v); }

  // Vertex v's wedges, ranked by their lowest corners (the corners are ascending, so a wedge's
  // root, its lowest index, is its lowest corner): appends (corner, rank) for each of its
  // corners if it has two or more, and returns how many.
  int64_t wedges(int64_t v, std::vector<std::pair<int64_t, int64_t>> &corner_rank) {
    const auto first =
        std::lower_bound(corners_.begin(), corners_.end(), std::pair<int64_t, int64_t>{v, -1}) -
        corners_.begin();
    auto last = first;
    while (last < static_cast<std::ptrdiff_t>(corners_.size()) && corners_[last].first == v)
      ++last;
    std::vector<int64_t> roots;
    for (auto i = first; i < last; ++i)
      if (find(parent_, i) == i)
        roots.push_back(i);
    if (roots.size() > 1)
      for (auto i = first; i < last; ++i) {
        const int64_t root = find(parent_, i);
        corner_rank.push_back({corners_[i].second,
                               std::lower_bound(roots.begin(), roots.end(), root) - roots.begin()});
      }
    return static_cast<int64_t>(roots.size());
  }

private:
  int64_t index(int64_t v, int64_t corner) const {
    return std::lower_bound(corners_.begin(), corners_.end(),
                            std::pair<int64_t, int64_t>{v, corner}) -
           corners_.begin();
  }

  std::vector<int64_t> split_;
  std::vector<std::pair<int64_t, int64_t>> corners_; // (vertex, corner), ascending
  std::vector<int64_t> parent_;
};

} // namespace

CornerCut cut_corners(const Topology &t, std::span<const int64_t> cut_edges,
                      std::span<const int64_t> split_vertices) {
  const int64_t nv = t.num_vertices();
  std::vector<uint8_t> is_cut(static_cast<std::size_t>(t.num_edges()), 0);
  std::vector<int64_t> cut_vertices(split_vertices.begin(), split_vertices.end());
  for (int64_t e : cut_edges) {
    is_cut[e] = 1;
    for (int64_t v : t.edge_vertices(e))
      cut_vertices.push_back(v);
  }
  std::sort(cut_vertices.begin(), cut_vertices.end());
  cut_vertices.erase(std::unique(cut_vertices.begin(), cut_vertices.end()), cut_vertices.end());
  SplitFans fans(t, is_cut, split_vertices);
  // Each vertex on the cut: the wedges of its fan between cut (or boundary) edges, one copy
  // each, numbered in the order of the wedges' lowest corners (3 cell + corner). Recorded as
  // (corner, wedge rank) per corner at the vertex, and the wedge count per cut vertex.
  std::vector<int64_t> wedges(cut_vertices.size());
  std::vector<std::pair<int64_t, int64_t>> corner_rank; // (corner, rank among v's copies)
  std::vector<int64_t> wedge_of, lowest, order, rank;
  Fan fan;
  for (std::size_t iv = 0; iv < cut_vertices.size(); ++iv) {
    const int64_t v = cut_vertices[iv];
    if (fans.holds(v)) {
      wedges[iv] = fans.wedges(v, corner_rank);
      continue;
    }
    walk_fan(t, v, fan);
    const std::size_t m = fan.cells.size();
    // A cycle starts after one of its cut crossings (an interior vertex on the cut has two).
    std::size_t first_cell = 0;
    if (fan.closed)
      for (std::size_t i = 0; i < m; ++i)
        if (is_cut[fan.crossed[i]]) {
          first_cell = (i + 1) % m;
          break;
        }
    wedge_of.assign(m, 0);
    lowest.clear();
    int64_t w = 0;
    for (std::size_t s = 0; s < m; ++s) {
      const std::size_t i = (first_cell + s) % m;
      if (s > 0 && is_cut[fan.crossed[(i + m - 1) % m]])
        ++w;
      const int64_t corner = 3 * fan.cells[i] + corner_of(t, fan.cells[i], v);
      if (static_cast<int64_t>(lowest.size()) <= w)
        lowest.push_back(corner);
      lowest[w] = std::min(lowest[w], corner);
      wedge_of[i] = w;
    }
    order.resize(lowest.size());
    std::iota(order.begin(), order.end(), int64_t{0});
    std::sort(order.begin(), order.end(),
              [&](int64_t a, int64_t b) { return lowest[a] < lowest[b]; });
    rank.resize(lowest.size());
    for (std::size_t r = 0; r < order.size(); ++r)
      rank[order[r]] = static_cast<int64_t>(r);
    if (lowest.size() > 1)
      for (std::size_t i = 0; i < m; ++i)
        corner_rank.push_back(
            {3 * fan.cells[i] + corner_of(t, fan.cells[i], v), rank[wedge_of[i]]});
    wedges[iv] = static_cast<int64_t>(lowest.size());
  }
  // The copies: every vertex once, a vertex on the cut once per wedge, in the originals' order.
  CornerCut out;
  out.first.resize(static_cast<std::size_t>(nv) + 1);
  int64_t extra = 0;
  std::size_t next_cut = 0;
  for (int64_t v = 0; v < nv; ++v) {
    out.first[v] = v + extra;
    if (next_cut < cut_vertices.size() && cut_vertices[next_cut] == v)
      extra += wedges[next_cut++] - 1;
  }
  out.first[nv] = nv + extra;
  out.vertex_origin.resize(static_cast<std::size_t>(nv + extra));
  for (int64_t v = 0; v < nv; ++v)
    for (int64_t i = out.first[v]; i < out.first[v + 1]; ++i)
      out.vertex_origin[i] = v;
  for (std::size_t iv = 0; iv < cut_vertices.size(); ++iv)
    if (wedges[iv] > 1) {
      const int64_t v = cut_vertices[iv];
      for (int64_t i = out.first[v]; i < out.first[v + 1]; ++i)
        out.copies.push_back(i);
      out.group_offset.push_back(static_cast<int64_t>(out.copies.size()));
    }
  std::sort(corner_rank.begin(), corner_rank.end());
  out.split_corners.reserve(corner_rank.size());
  for (const auto &[corner, r] : corner_rank)
    out.split_corners.push_back({corner, out.first[t.cell_vertices(corner / 3)[corner % 3]] + r});
  return out;
}

int64_t CornerCut::corner_vertex(const Topology &t, int64_t c, int k) const {
  const int64_t v = t.cell_vertices(c)[k];
  if (first[v + 1] - first[v] == 1)
    return first[v];
  const auto at = std::lower_bound(split_corners.begin(), split_corners.end(),
                                   std::pair<int64_t, int64_t>{3 * c + k, -1});
  return at->second;
}

std::vector<int64_t> corner_vertices(const Topology &t, const CornerCut &cut) {
  std::vector<int64_t> out(static_cast<std::size_t>(3 * t.num_cells()));
  for (int64_t c = 0; c < t.num_cells(); ++c)
    for (int k = 0; k < 3; ++k)
      out[3 * c + k] = cut.first[t.cell_vertices(c)[k]];
  for (const auto &[corner, v] : cut.split_corners)
    out[corner] = v;
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
        s[2 * side + k] = cut.corner_vertex(t, c, corner_of(t, c, ends[k]));
    }
    seams.push_back(s);
  }
  return seams;
}

CutSurface cut_open(const Mesh &mesh, std::span<const int64_t> cut_edges,
                    std::span<const int64_t> split_vertices) {
  const Topology &t = mesh.topology;
  std::vector<uint8_t> is_cut(static_cast<std::size_t>(t.num_edges()), 0);
  for (int64_t e : cut_edges)
    is_cut[e] = 1;
  CornerCut corner_cut = cut_corners(t, cut_edges, split_vertices);
  CutSurface out;
  std::vector<int64_t> edge_origin;
  Topology cut = t.cut_open(corner_cut.first, corner_cut.split_corners, is_cut, &edge_origin);
  out.vertex_origin = std::move(corner_cut.vertex_origin);
  out.group_offset = std::move(corner_cut.group_offset);
  out.copies = std::move(corner_cut.copies);
  // Every component a disk (Euler characteristic 1, one boundary loop) or a sphere left whole
  // (2, none: its cut graph is empty).
  const auto disks = [&](const Topology &x) {
    const int64_t loops = x.boundary_loops(), spheres = x.components() - loops;
    return x.components() == t.components() && spheres >= 0 &&
           x.euler_characteristic() == loops + 2 * spheres;
  };
  if (!disks(cut))
    throw Error((mesh.source.empty() ? std::string("the mesh") : mesh.source) +
                ": cutting the surface open along " + std::to_string(cut_edges.size()) +
                " edges did not give one disk (or sphere) per component (Euler characteristic " +
                std::to_string(cut.euler_characteristic()) + ", " +
                std::to_string(cut.boundary_loops()) + " boundary loops, " +
                std::to_string(cut.components()) + " components): an internal error");
  // Each cut edge's copies: the edge of its first cell, then of its second, in the cut mesh.
  out.seams.reserve(cut_edges.size());
  for (int64_t e : cut_edges) {
    std::array<int64_t, 2> seam{};
    for (int side = 0; side < 2; ++side) {
      const int64_t c = t.edge_cells_begin(e)[side];
      seam[side] = cut.cell_edge(c, t.local_edge(c, e));
    }
    out.seams.push_back(seam);
  }

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
