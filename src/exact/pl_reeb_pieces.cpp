#include "exact/pl_reeb_pieces.hpp"

#include "exact/piece_arcs.hpp"
#include "exact/piece_keys.hpp"
#include "mesh/cut_surface.hpp"
#include "mesh/topology.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/error.hpp"
#include "util/parallel_sort.hpp"

#include <algorithm>
#include <numeric>

namespace hoct {
ReebGroup pl_reeb_group(const PlPieceMesh &m, const PiecePlace &place, bool augmented, int threads,
                        PieceArcGraph *arcs) {
  const PlMesh &pl = m.pl;
  const bool all = m.point.empty();
  auto at = [&](int64_t i) { return all ? i : m.point[i]; };
  auto index = [&](int64_t p) { return all ? p : m.local[p]; };
  const int64_t n = all ? pl.num_vertices() : static_cast<int64_t>(m.point.size());
  const auto mine = [&](const std::array<int32_t, 2> &s) {
    return within(s, place.piece, place.piece);
  };
  // The PL triangles' topology over the sweeps' vertices, open where other pieces go on.
  MeshInput corners;
  corners.points.resize(static_cast<std::size_t>(n));
  corners.cell_nodes.reserve(pl.triangles.size() * 3);
  for (const auto &t : pl.triangles) {
    const int64_t ids[3] = {index(t[0]), index(t[1]), index(t[2])};
    corners.add_cell(1, ids);
  }
  std::vector<uint8_t> open(static_cast<std::size_t>(n));
  for (int64_t i = 0; i < n; ++i)
    open[i] = !mine(m.span[at(i)]);
  ProblemLog problems;
  const Topology topo = Topology::build(corners, problems, threads, open);
  corners = MeshInput{};
  if (problems.has_errors())
    throw Error("a piece's piecewise-linear mesh is not a surface (an internal error):\n" +
                problems.summary());
  // Cut into disks: along its cut graph, and apart at its open points.
  const std::vector<int64_t> cuts = cut_graph_edges(topo);
  std::vector<int64_t> split;
  for (int64_t v = 0; v < topo.num_vertices(); ++v)
    if (open[topo.vertex_point(v)])
      split.push_back(v);
  const CornerCut cut = cut_corners(topo, cuts, split);
  const int64_t nc = static_cast<int64_t>(cut.vertex_origin.size());
  std::vector<int64_t> point(static_cast<std::size_t>(nc)); // each copy's point of pl
  std::vector<double> values(static_cast<std::size_t>(nc));
  for (int64_t c = 0; c < nc; ++c) {
    point[c] = at(topo.vertex_point(cut.vertex_origin[c]));
    values[c] = pl.values[point[c]];
  }
  std::vector<int64_t> order(static_cast<std::size_t>(nc));
  std::iota(order.begin(), order.end(), int64_t{0});
  parallel_sort(order.begin(), order.end(), threads, [&](int64_t x, int64_t y) {
    return values[x] < values[y] ||
           (values[x] == values[y] &&
            (m.key[point[x]] < m.key[point[y]] || (m.key[point[x]] == m.key[point[y]] && x < y)));
  });
  const std::vector<int64_t> cv = corner_vertices(topo, cut);
  std::vector<GraphEdge> edges(cv.size());
  for (std::size_t t = 0; t < cv.size() / 3; ++t)
    for (int k = 0; k < 3; ++k)
      edges[3 * t + k] = {cv[3 * t + k], cv[3 * t + (k + 1) % 3]};
  // Kept: the copies of cut and open points, and the vertices other pieces hold.
  std::vector<uint8_t> keep(static_cast<std::size_t>(nc), augmented ? 1 : 0);
  for (int64_t c = 0; c < nc; ++c) {
    const int64_t v = cut.vertex_origin[c];
    keep[c] = keep[c] || !mine(m.span[point[c]]) || cut.first[v + 1] - cut.first[v] > 1;
  }
  const std::vector<std::array<int64_t, 4>> seams = seam_vertices(topo, cut, cuts);
  for (const auto &s : seams)
    for (const int64_t c : s)
      keep[c] = 1;
  std::vector<int64_t> kept_copies;
  const PieceTrees trees =
      pl_kept_trees(m, place, values, edges, keep, order, point, threads, &kept_copies);
  std::vector<int64_t> kept(static_cast<std::size_t>(nc), -1);
  for (std::size_t k = 0; k < kept_copies.size(); ++k)
    kept[kept_copies[k]] = static_cast<int64_t>(k);
  // The sides to glue, one PL edge each from its lower key: both copies of each cut edge, and
  // the border edges other pieces may hold (the pieces of an edge's cells hold both its ends).
  std::vector<ReebChain> chains;
  const auto side = [&](int64_t a, int64_t b, const std::array<int32_t, 2> &span) {
    if (m.key[point[b]] < m.key[point[a]])
      std::swap(a, b);
    if (kept[a] < 0 || kept[b] < 0)
      throw std::logic_error("pl_reeb_group: an end of a seam was not kept");
    ReebChain r;
    r.lo = m.key[point[a]];
    r.hi = m.key[point[b]];
    r.span = span;
    r.nodes = {kept[a], kept[b]};
    chains.push_back(std::move(r));
  };
  std::vector<uint8_t> is_cut(static_cast<std::size_t>(topo.num_edges()), 0);
  for (const int64_t e : cuts)
    is_cut[e] = 1;
  for (const auto &s : seams) {
    side(s[0], s[1], {place.piece, place.piece});
    side(s[2], s[3], {place.piece, place.piece});
  }
  for (int64_t e = 0; e < topo.num_edges(); ++e) {
    if (!topo.is_boundary_edge(e) || is_cut[e])
      continue;
    const auto &ev = topo.edge_vertices(e);
    const auto &sa = m.span[at(topo.vertex_point(ev[0]))],
               &sb = m.span[at(topo.vertex_point(ev[1]))];
    const std::array<int32_t, 2> span{std::max(sa[0], sb[0]), std::min(sa[1], sb[1])};
    if (mine(span))
      continue; // on the whole's boundary
    const int64_t c = topo.edge_cells_begin(e)[0];
    int64_t ends[2] = {-1, -1};
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 2; ++j)
        if (topo.cell_vertices(c)[k] == ev[j])
          ends[j] = cut.corner_vertex(topo, c, k);
    side(ends[0], ends[1], span);
  }
  if (arcs) {
    std::vector<int64_t> points(kept_copies.size());
    for (std::size_t k = 0; k < points.size(); ++k)
      points[k] = point[static_cast<std::size_t>(kept_copies[k])];
    pl_arc_graph(m, place, trees, std::move(points), *arcs);
  }
  return reeb_group(trees, std::move(chains), augmented);
}

TreeResult pl_reeb_graph_of_group(const ReebGroup &all, bool augmented, const std::string &method,
                                  const PlCounts &counts, double reference) {
  TreeResult r = reeb_graph_of_group(all, augmented, reference);
  mark_pl_result(r, method, counts);
  return r;
}

} // namespace hoct
