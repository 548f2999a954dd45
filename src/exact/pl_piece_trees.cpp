#include "exact/pl_piece_trees.hpp"

#include "exact/piece_keys.hpp"
#include "pl/pl_mesh.hpp"
#include "pl/refinement.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/parallel_sort.hpp"

#include <numeric>
#include <stdexcept>

namespace hoct {
namespace {

// The kept trees of a piece's PL mesh over its vertices `point` (indices into pl; empty: every
// point of pl, `local` then empty too; else local[p] is point p's index in it), which `less`
// orders as the whole orders them; keep[i]: vertex i is kept whatever it is; node(p) makes the
// kept node of pl point p.
template <class Less, class Node>
PieceTrees kept_trees(const PlMesh &pl, const std::vector<int64_t> &point,
                      const std::vector<int64_t> &local, const std::vector<uint8_t> &keep,
                      int piece, int threads, Less less, Node node) {
  const bool all = point.empty();
  auto at = [&](int64_t i) { return all ? i : point[i]; };
  auto index = [&](int64_t p) { return all ? p : local[p]; };
  const int64_t n = all ? pl.num_vertices() : static_cast<int64_t>(point.size());
  std::vector<double> values(static_cast<std::size_t>(n));
  for (int64_t i = 0; i < n; ++i)
    values[i] = pl.values[at(i)];
  std::vector<int64_t> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), int64_t{0});
  parallel_sort(order.begin(), order.end(), threads, [&](int64_t x, int64_t y) {
    return values[x] < values[y] || (values[x] == values[y] && less(at(x), at(y)));
  });
  std::vector<GraphEdge> edges(pl.triangles.size() * 3);
  for (std::size_t t = 0; t < pl.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      edges[3 * t + k] = {index(pl.triangles[t][k]), index(pl.triangles[t][(k + 1) % 3])};
  const KeptMergeTrees kt = sweep_merge_trees(values, {edges, {}, {}}, keep, threads, order);
  PieceTrees trees;
  trees.first_piece = trees.last_piece = piece;
  trees.join_parent = kt.join_parent;
  trees.split_parent = kt.split_parent;
  trees.nodes.resize(kt.nodes.size());
  for (std::size_t k = 0; k < kt.nodes.size(); ++k) {
    PieceNode &m = trees.nodes[k];
    m = node(at(kt.nodes[k]));
    m.value = values[kt.nodes[k]];
    m.shared = !within(m.span, piece, piece);
  }
  return trees;
}

} // namespace

PlPieceTrees pl_piece_trees(const MeshInput &piece, const PiecePlace &place, bool augmented,
                            int threads) {
  if (!nodal_lagrange_cells(piece))
    throw std::invalid_argument("pl_piece_trees: cells other than Lagrange triangles and "
                                "quadrilaterals");
  const PlMesh pl = split_lagrange_cells(piece, /*keep_unused_points=*/true);
  // The sweeps' vertices: the points the piece's cells use, in the piece's order.
  const int64_t np = static_cast<int64_t>(pl.points.size());
  std::vector<int64_t> local(static_cast<std::size_t>(np), -1), point;
  point.reserve(static_cast<std::size_t>(np));
  PlPieceTrees out;
  for (int64_t p = 0; p < np; ++p)
    if (pl.source_cell[p] >= 0) {
      local[p] = static_cast<int64_t>(point.size());
      point.push_back(p);
      out.own_points += place.point_span[p][0] == place.piece;
    }
  std::vector<uint8_t> keep(point.size());
  for (std::size_t i = 0; i < point.size(); ++i)
    keep[i] = augmented || !within(place.point_span[point[i]], place.piece, place.piece);
  // Ties by the point's index in the whole: the whole's PL tree's order.
  out.trees = kept_trees(
      pl, point, local, keep, place.piece, threads,
      [&](int64_t p, int64_t q) { return place.global_point[p] < place.global_point[q]; },
      [&](int64_t p) {
        PieceNode m;
        m.key = {NodeKey::Vertex, place.global_point[p], 0, 0};
        m.span = place.point_span[p];
        // The first cell that has the vertex wins (one_node keeps the lower order_cell).
        m.order_cell = m.cell = place.first_cell + pl.source_cell[p];
        m.uv = pl.source_uv[p];
        m.location = classify_location(m.uv[0], m.uv[1]);
        m.position = pl.points[p];
        return m;
      });
  out.triangles = static_cast<int64_t>(pl.triangles.size());
  return out;
}

PlPieceTrees refined_piece_trees(const Mesh &mesh, const PiecePlace &place, int k, bool augmented,
                                 int threads) {
  const PlMesh pl = refine(mesh, k);
  const Topology &topo = mesh.topology;
  const int64_t nv = topo.num_vertices(), ne = topo.num_edges(), np = pl.num_vertices();
  const int64_t steps = std::max(k - 1, 0), interior = nv + ne * steps;
  // Each point's key, span and placing triangle, as the whole's refinement numbers and places
  // it (pl/refinement: vertices, then every edge's lattice points from its lower point, then
  // each triangle's own).
  std::vector<NodeKey> key(static_cast<std::size_t>(np));
  std::vector<std::array<int32_t, 2>> span(static_cast<std::size_t>(np));
  std::vector<int64_t> triangle(static_cast<std::size_t>(np));
  auto point = [&](int64_t v) { return place.global_point[topo.vertex_point(v)]; };
  PlPieceTrees out;
  for (int64_t v = 0; v < nv; ++v) {
    key[v] = {NodeKey::Vertex, point(v), 0, 0};
    span[v] = place.point_span[topo.vertex_point(v)];
    triangle[v] = topo.vertex_cell(v);
    out.own_points += span[v][0] == place.piece;
  }
  for (int64_t e = 0; e < ne; ++e) {
    const auto &ev = topo.edge_vertices(e);
    const auto &sa = span[ev[0]], &sb = span[ev[1]];
    // The pieces of an edge's cells hold both its ends.
    const std::array<int32_t, 2> s{std::max(sa[0], sb[0]), std::min(sa[1], sb[1])};
    for (int64_t j = 0; j < steps; ++j) {
      const int64_t p = nv + e * steps + j;
      key[p] = {NodeKey::EdgeNode, point(ev[0]), point(ev[1]), j};
      span[p] = s;
      triangle[p] = topo.edge_cells_begin(e)[0];
    }
  }
  for (int64_t p = interior, rank = 0; p < np; ++p) {
    const int64_t c = pl.source_cell[p];
    rank = p > interior && pl.source_cell[p - 1] == c ? rank + 1 : 0;
    key[p] = {NodeKey::Interior, place.first_triangle + c, 0, rank};
    span[p] = {place.piece, place.piece};
    triangle[p] = c;
  }
  out.cell_points = np - interior;
  std::vector<uint8_t> keep(static_cast<std::size_t>(np));
  for (int64_t p = 0; p < np; ++p)
    keep[p] = augmented || !within(span[p], place.piece, place.piece);
  out.trees = kept_trees(
      pl, {}, {}, keep, place.piece, threads, [&](int64_t p, int64_t q) { return key[p] < key[q]; },
      [&](int64_t p) {
        PieceNode m;
        m.key = key[p];
        m.span = span[p];
        m.order_cell = place.first_triangle + triangle[p];
        m.position = pl.points[p];
        // Classified in the triangle, reported in the input cell (as compute_tree does).
        m.location = classify_location(pl.source_uv[p][0], pl.source_uv[p][1]);
        const CellPlace c = mesh.origins.to_input(pl.source_cell[p], pl.source_uv[p]);
        m.cell = place.first_cell + c.cell;
        m.uv = c.uv;
        return m;
      });
  out.triangles = static_cast<int64_t>(pl.triangles.size());
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
  r.method = method;
  r.stats.exact.reset();
  r.stats.pl = counts;
  return r;
}

} // namespace hoct
