#include "exact/piece_keys.hpp"

#include "cell/strict_extrema.hpp"
#include "tree/node_order.hpp"

namespace hoct {

int lattice_steps(const Mesh &mesh, const ExactTreeOptions &options) {
  return options.fallback_refinement > 0 ? options.fallback_refinement
                                         : std::max(4, 2 * std::max(1, mesh.field.max_degree()));
}

std::vector<int64_t> key_order(std::span<const double> values, const PieceKeys &keys, int threads) {
  // Ids follow the keys but for fallback nodes (and a cut's copies): only runs of equal values
  // need sorting by key.
  std::vector<int64_t> order = ascending_order(values, threads);
  const int64_t n = static_cast<int64_t>(order.size());
  for (int64_t i = 0; i < n;) {
    int64_t j = i + 1;
    while (j < n && values[order[j]] == values[order[i]])
      ++j;
    if (j - i > 1)
      std::sort(order.begin() + i, order.begin() + j, [&](int64_t x, int64_t y) {
        const NodeKey a = keys.key(x), b = keys.key(y);
        return a < b || (a == b && x < y); // a cut's copies of one point: by id
      });
    i = j;
  }
  return order;
}

std::vector<PieceNode> piece_nodes(const Mesh &mesh, const PiecePlace &place,
                                   const ExactGraphBuild &b, const PieceKeys &keys,
                                   std::span<const int64_t> ids, std::span<const uint8_t> shared) {
  const ExactGraph &g = b.graph;
  // Shared vertices and edge nodes: their slack before the certain extrema are taken out, and
  // what this piece's edges and cells say of their certainty.
  std::vector<uint8_t> wanted(static_cast<std::size_t>(mesh.topology.num_vertices()), 0);
  for (const int64_t id : ids)
    if (id < g.edge_base && shared[id])
      wanted[id] = 1;
  const std::vector<uint8_t> strict_vertex =
      strict_vertex_extrema(mesh.topology, mesh.field, wanted);
  auto slack_in = [](const std::vector<std::pair<int64_t, double>> &errors, int64_t id) {
    auto it = std::lower_bound(errors.begin(), errors.end(), std::pair<int64_t, double>{id, -1.0});
    return it != errors.end() && it->first == id ? it->second : -1.0;
  };
  std::vector<PieceNode> out(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const int64_t id = ids[i];
    PieceNode &p = out[i];
    p.key = keys.key(id);
    p.value = g.values[id];
    p.span = keys.span(id);
    const NodeSource s = g.source(mesh.topology, b.edge_nodes, id);
    p.order_cell = place.first_triangle + s.cell;
    p.position = mesh.geometry.position(s.cell, s.uv[0], s.uv[1]);
    const CellPlace c =
        mesh.origins.identity() ? CellPlace{s.cell, s.uv} : mesh.origins.to_input(s.cell, s.uv);
    p.cell = place.first_cell + c.cell;
    p.uv = c.uv;
    p.location = s.location;
    p.fallback = s.fallback;
    p.shared = id < g.tail_base && shared[id];
    if (!p.shared) {
      p.slack = slack_in(b.degenerate.node_error, id);
      continue;
    }
    p.slack = slack_in(b.degenerate.node_bound, id);
    if (id < g.edge_base) {
      p.strict = strict_vertex[id];
    } else {
      const int64_t k = id - g.edge_base;
      const auto &off = b.edge_nodes.offset;
      const int64_t e = std::upper_bound(off.begin(), off.end(), k) - off.begin() - 1;
      if (strict_edge_extremum(mesh.topology, mesh.field, b.edge_nodes, e, k))
        p.strict = b.edge_nodes.nodes[k].second > 0 ? 1 : 2;
    }
  }
  return out;
}

} // namespace hoct
