#include "exact/pl_piece_trees.hpp"

#include "exact/piece_arcs.hpp"
#include "exact/piece_keys.hpp"
#include "pl/pl_mesh.hpp"
#include "pl/refinement.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/parallel_sort.hpp"

#include <numeric>
#include <stdexcept>

namespace hoct {
namespace {

// The kept trees of a piece's PL mesh (linear_piece_mesh, refined_piece_mesh) over its sweeps'
// vertices, ordered as the whole orders them; keep[i]: vertex i is kept whatever it is. With
// `arcs`, the piece's PL graph there (its 1-skeleton), to draw the whole tree's arcs.
PieceTrees kept_trees(const PlPieceMesh &m, const PiecePlace &place,
                      const std::vector<uint8_t> &keep, int threads, PieceArcGraph *arcs) {
  const PlMesh &pl = m.pl;
  const bool all = m.point.empty();
  auto at = [&](int64_t i) { return all ? i : m.point[i]; };
  auto index = [&](int64_t p) { return all ? p : m.local[p]; };
  const int64_t n = all ? pl.num_vertices() : static_cast<int64_t>(m.point.size());
  std::vector<double> values(static_cast<std::size_t>(n));
  for (int64_t i = 0; i < n; ++i)
    values[i] = pl.values[at(i)];
  std::vector<int64_t> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), int64_t{0});
  parallel_sort(order.begin(), order.end(), threads, [&](int64_t x, int64_t y) {
    return values[x] < values[y] || (values[x] == values[y] && m.key[at(x)] < m.key[at(y)]);
  });
  std::vector<GraphEdge> edges(pl.triangles.size() * 3);
  for (std::size_t t = 0; t < pl.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      edges[3 * t + k] = {index(pl.triangles[t][k]), index(pl.triangles[t][(k + 1) % 3])};
  std::vector<int64_t> kept;
  PieceTrees trees = pl_kept_trees(m, place, values, edges, keep, order, m.point, threads, &kept);
  if (arcs) {
    for (int64_t &k : kept)
      k = at(k);
    pl_arc_graph(m, place, trees, std::move(kept), *arcs);
  }
  return trees;
}

} // namespace

PieceTrees pl_kept_trees(const PlPieceMesh &m, const PiecePlace &place,
                         std::span<const double> values, std::span<const GraphEdge> edges,
                         std::span<const uint8_t> keep, std::span<const int64_t> order,
                         std::span<const int64_t> point, int threads, std::vector<int64_t> *kept) {
  const KeptMergeTrees kt = sweep_merge_trees(values, {edges, {}, {}}, keep, threads, order);
  if (kept)
    *kept = kt.nodes;
  PieceTrees trees;
  trees.first_piece = trees.last_piece = place.piece;
  trees.join_parent = kt.join_parent;
  trees.split_parent = kt.split_parent;
  trees.nodes.resize(kt.nodes.size());
  for (std::size_t k = 0; k < kt.nodes.size(); ++k) {
    const int64_t i = kt.nodes[k];
    PieceNode &node = trees.nodes[k];
    node = pl_piece_node(m, place, point.empty() ? i : point[static_cast<std::size_t>(i)]);
    node.value = values[i];
  }
  return trees;
}

void pl_arc_graph(const PlPieceMesh &m, const PiecePlace &place, const PieceTrees &trees,
                  std::vector<int64_t> points, PieceArcGraph &arcs) {
  const PlMesh &pl = m.pl;
  const ScalarGraph g = pl.graph();
  auto graph = std::make_shared<GeometricGraph>(pl.points, pl.values);
  for (int64_t v = 0; v < g.size(); ++v)
    for (const int64_t u : g.neighbors(v))
      if (u > v)
        graph->add_edge(v, u);
  graph->finish();
  arcs.graph = std::move(graph);
  arcs.set_kept(place.piece, trees, std::move(points));
}

PieceNode pl_piece_node(const PlPieceMesh &m, const PiecePlace &place, int64_t p) {
  PieceNode node;
  node.key = m.key[p];
  node.span = m.span[p];
  node.position = m.pl.points[p];
  node.shared = !within(node.span, place.piece, place.piece);
  if (!m.refined) {
    // The first cell that has the vertex wins (one_node keeps the lower order_cell).
    node.order_cell = node.cell = place.first_cell + m.pl.source_cell[p];
    node.uv = m.pl.source_uv[p];
    node.location = classify_location(node.uv[0], node.uv[1]);
    return node;
  }
  node.order_cell = place.first_triangle + m.triangle[p];
  // Classified in the triangle, reported in the input cell (as compute_tree does).
  node.location = classify_location(m.pl.source_uv[p][0], m.pl.source_uv[p][1]);
  const CellPlace c = m.refined->origins.to_input(m.pl.source_cell[p], m.pl.source_uv[p]);
  node.cell = place.first_cell + c.cell;
  node.uv = c.uv;
  return node;
}

PlPieceMesh linear_piece_mesh(const MeshInput &piece, const PiecePlace &place) {
  if (!nodal_lagrange_cells(piece))
    throw std::invalid_argument("pl_piece_trees: cells other than Lagrange triangles and "
                                "quadrilaterals");
  PlPieceMesh m;
  m.pl = split_lagrange_cells(piece, /*keep_unused_points=*/true);
  // The sweeps' vertices: the points the piece's cells use, in the piece's order; named by their
  // point in the whole (ties by its index: the whole's PL tree's order).
  const int64_t np = static_cast<int64_t>(m.pl.points.size());
  m.local.assign(static_cast<std::size_t>(np), -1);
  m.point.reserve(static_cast<std::size_t>(np));
  m.key.resize(static_cast<std::size_t>(np));
  m.span.resize(static_cast<std::size_t>(np));
  for (int64_t p = 0; p < np; ++p) {
    m.key[p] = {NodeKey::Vertex, place.global_point[p], 0, 0};
    m.span[p] = place.point_span[p];
    if (m.pl.source_cell[p] >= 0) {
      m.local[p] = static_cast<int64_t>(m.point.size());
      m.point.push_back(p);
      m.own_points += place.point_span[p][0] == place.piece;
    }
  }
  return m;
}

PlPieceMesh refined_piece_mesh(const Mesh &mesh, const PiecePlace &place, int k) {
  PlPieceMesh m;
  m.pl = refine(mesh, k);
  m.refined = &mesh;
  const Topology &topo = mesh.topology;
  const int64_t nv = topo.num_vertices(), ne = topo.num_edges(), np = m.pl.num_vertices();
  const int64_t steps = std::max(k - 1, 0), interior = nv + ne * steps;
  // Each point's key, span and placing triangle, as the whole's refinement numbers and places
  // it (pl/refinement: vertices, then every edge's lattice points from its lower point, then
  // each triangle's own).
  m.key.resize(static_cast<std::size_t>(np));
  m.span.resize(static_cast<std::size_t>(np));
  m.triangle.resize(static_cast<std::size_t>(np));
  auto point = [&](int64_t v) { return place.global_point[topo.vertex_point(v)]; };
  for (int64_t v = 0; v < nv; ++v) {
    m.key[v] = {NodeKey::Vertex, point(v), 0, 0};
    m.span[v] = place.point_span[topo.vertex_point(v)];
    m.triangle[v] = topo.vertex_cell(v);
    m.own_points += m.span[v][0] == place.piece;
  }
  for (int64_t e = 0; e < ne; ++e) {
    const auto &ev = topo.edge_vertices(e);
    const auto &sa = m.span[ev[0]], &sb = m.span[ev[1]];
    // The pieces of an edge's cells hold both its ends.
    const std::array<int32_t, 2> s{std::max(sa[0], sb[0]), std::min(sa[1], sb[1])};
    for (int64_t j = 0; j < steps; ++j) {
      const int64_t p = nv + e * steps + j;
      m.key[p] = {NodeKey::EdgeNode, point(ev[0]), point(ev[1]), j};
      m.span[p] = s;
      m.triangle[p] = topo.edge_cells_begin(e)[0];
    }
  }
  for (int64_t p = interior, rank = 0; p < np; ++p) {
    const int64_t c = m.pl.source_cell[p];
    rank = p > interior && m.pl.source_cell[p - 1] == c ? rank + 1 : 0;
    m.key[p] = {NodeKey::Interior, place.first_triangle + c, 0, rank};
    m.span[p] = {place.piece, place.piece};
    m.triangle[p] = c;
  }
  m.cell_points = np - interior;
  return m;
}

PlPieceTrees pl_piece_trees(const MeshInput &piece, const PiecePlace &place, bool augmented,
                            int threads, PieceArcGraph *arcs) {
  const PlPieceMesh m = linear_piece_mesh(piece, place);
  std::vector<uint8_t> keep(m.point.size());
  for (std::size_t i = 0; i < m.point.size(); ++i)
    keep[i] = augmented || !within(m.span[m.point[i]], place.piece, place.piece);
  PlPieceTrees out;
  out.trees = kept_trees(m, place, keep, threads, arcs);
  out.own_points = m.own_points;
  out.triangles = static_cast<int64_t>(m.pl.triangles.size());
  return out;
}

PlPieceTrees refined_piece_trees(const Mesh &mesh, const PiecePlace &place, int k, bool augmented,
                                 int threads, PieceArcGraph *arcs) {
  const PlPieceMesh m = refined_piece_mesh(mesh, place, k);
  const int64_t np = m.pl.num_vertices();
  std::vector<uint8_t> keep(static_cast<std::size_t>(np));
  for (int64_t p = 0; p < np; ++p)
    keep[p] = augmented || !within(m.span[p], place.piece, place.piece);
  PlPieceTrees out;
  out.trees = kept_trees(m, place, keep, threads, arcs);
  out.own_points = m.own_points;
  out.cell_points = m.cell_points;
  out.triangles = static_cast<int64_t>(m.pl.triangles.size());
  return out;
}

PlCounts whole_pl_counts(int64_t triangles, int64_t own_points, int64_t cell_points, int k,
                         int64_t euler_characteristic) {
  PlCounts c{own_points, triangles};
  if (k > 0) {
    const int64_t mesh_triangles = triangles / (int64_t{k} * k);
    const int64_t edges = own_points + mesh_triangles - euler_characteristic;
    c.vertices = own_points + edges * (k - 1) + cell_points;
  }
  return c;
}

TreeResult pl_tree_of_pieces(const PieceTrees &all, bool augmented, const std::string &method,
                             const PlCounts &counts, double reference) {
  TreeResult r = tree_of_pieces(all, augmented, reference);
  mark_pl_result(r, method, counts);
  return r;
}

void mark_pl_result(TreeResult &r, const std::string &method, const PlCounts &counts) {
  r.method = method;
  r.stats.exact.reset();
  r.stats.pl = counts;
}

} // namespace hoct
