#include "exact/piece_trees.hpp"

#include "cell/strict_extrema.hpp"
#include "exact/exact_arc_graph.hpp"
#include "exact/exact_graph_build.hpp"
#include "exact/graph_sweeps.hpp"
#include "exact/piece_arcs.hpp"
#include "exact/piece_keys.hpp"
#include "tree/node_order.hpp"
#include "tree/stand_in_contraction.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace hoct {
namespace {

bool before(const PieceNode &x, const PieceNode &y) {
  return x.value < y.value || (x.value == y.value && x.key < y.key);
}

} // namespace

PieceTrees piece_trees(const Mesh &mesh, const PiecePlace &place, const ExactTreeOptions &options,
                       TreeTimings &time, PieceArcGraph *arcs) {
  ExactTreeOptions eo = options;
  eo.arc_geometry = arcs != nullptr;
  eo.cut = nullptr;
  ExactGraphBuild b = build_exact_graph(mesh, eo, time);
  ExactGraph &g = b.graph;
  const PieceKeys keys(mesh, place, b, lattice_steps(mesh, eo));
  const int64_t n = g.size();
  const int threads = threads_for(n, thread_count(eo.threads), 8 * eo.cells_per_thread);
  const std::vector<int64_t> order = key_order(g.values, keys, threads);
  // Kept: nodes other pieces may hold too (and every node of an augmented tree).
  std::vector<uint8_t> keep(static_cast<std::size_t>(n), eo.augmented ? 1 : 0);
  if (!eo.augmented)
    for (int64_t id = 0; id < g.tail_base; ++id)
      keep[id] = !within(keys.span(id), place.piece, place.piece);
  for (const auto &[e, t, id] : b.degenerate.lattice_on_edge)
    keep[id] = eo.augmented || !within(keys.span(id), place.piece, place.piece);
  // The chains of edges other pieces may hold wait for the group that has all their cells
  // (SharedChain): left out of this sweep, listed ones (with lattice nodes) too.
  const Topology &topo = mesh.topology;
  const EdgeNodes &en = b.edge_nodes;
  auto edge_span = [&](int64_t e) { return keys.edge_span(e); };
  std::vector<uint8_t> shared_edge(static_cast<std::size_t>(topo.num_edges()), 0);
  for (int64_t e = 0; e < topo.num_edges(); ++e)
    shared_edge[e] = !within(edge_span(e), place.piece, place.piece);
  const std::vector<int64_t> &listed = g.listed_chains;
  std::vector<int64_t> skip;
  for (std::size_t e = 0, l = 0; e < shared_edge.size(); ++e) {
    while (l < listed.size() && listed[l] < static_cast<int64_t>(e))
      ++l;
    if (shared_edge[e] || (l < listed.size() && listed[l] == static_cast<int64_t>(e)))
      skip.push_back(static_cast<int64_t>(e));
  }
  // The listed chains' pieces close common_edges (add_edge_chains): those of shared edges out.
  const auto &lattice = b.degenerate.lattice_on_edge;
  std::vector<GraphEdge> common;
  if (eo.arc_geometry) {
    // The graph lists every chain's pieces (common_edges[chain_first ..], edge by edge): those
    // of the edges the piece holds alone.
    common.assign(g.common_edges.begin(),
                  g.common_edges.begin() + static_cast<std::ptrdiff_t>(g.chain_first));
    std::size_t at = g.chain_first, l = 0;
    for (int64_t e = 0; e < topo.num_edges(); ++e) {
      std::size_t n = static_cast<std::size_t>(1 + en.count(e));
      for (; l < lattice.size() && std::get<0>(lattice[l]) <= e; ++l)
        n += std::get<0>(lattice[l]) == e;
      if (!shared_edge[e])
        common.insert(common.end(), g.common_edges.begin() + static_cast<std::ptrdiff_t>(at),
                      g.common_edges.begin() + static_cast<std::ptrdiff_t>(at + n));
      at += n;
    }
    if (at != g.common_edges.size())
      throw std::logic_error("piece_trees: edge chain pieces miscounted");
    skip.clear();
  } else {
    std::size_t listed_pieces = lattice.size();
    for (const int64_t e : listed)
      listed_pieces += static_cast<std::size_t>(1 + en.count(e));
    const std::size_t prefix = g.common_edges.size() - listed_pieces;
    common.assign(g.common_edges.begin(), g.common_edges.begin() + prefix);
    std::size_t at = prefix, l = 0;
    for (const int64_t e : listed) {
      std::size_t n = static_cast<std::size_t>(1 + en.count(e));
      for (; l < lattice.size() && std::get<0>(lattice[l]) <= e; ++l)
        n += std::get<0>(lattice[l]) == e;
      if (!shared_edge[e])
        common.insert(common.end(), g.common_edges.begin() + at, g.common_edges.begin() + at + n);
      at += n;
    }
  }
  SweepEdges edges = exact_sweep_edges(mesh, en, g, eo);
  edges.common = common;
  edges.chains.skip = skip;
  const KeptMergeTrees kt = sweep_merge_trees(g.values, edges, keep, threads, order);

  PieceTrees out;
  out.first_piece = out.last_piece = place.piece;
  out.join_parent = kt.join_parent;
  out.split_parent = kt.split_parent;
  // Vertices and edge nodes other pieces may hold.
  std::vector<uint8_t> shared(static_cast<std::size_t>(g.tail_base), 0);
  for (int64_t id = 0; id < g.tail_base; ++id)
    shared[id] = !within(keys.span(id), place.piece, place.piece);
  out.nodes = piece_nodes(mesh, place, b, keys, kt.nodes, shared);
  // The shared edges' chains, by the kept nodes' indices.
  std::unordered_map<int64_t, int64_t> index_of;
  for (std::size_t i = 0; i < kt.nodes.size(); ++i)
    index_of[kt.nodes[i]] = static_cast<int64_t>(i);
  auto kept = [&](int64_t id) {
    auto it = index_of.find(id);
    if (it == index_of.end())
      throw std::logic_error("piece_trees: a node of a shared edge was not kept");
    return it->second;
  };
  std::size_t l = 0;
  for (int64_t e = 0; e < topo.num_edges(); ++e) {
    while (l < lattice.size() && std::get<0>(lattice[l]) < e)
      ++l;
    if (!shared_edge[e])
      continue;
    SharedChain c;
    const auto &ev = topo.edge_vertices(e);
    c.lo = place.global_point[topo.vertex_point(ev[0])];
    c.hi = place.global_point[topo.vertex_point(ev[1])];
    c.span = edge_span(e);
    c.nodes.push_back({0.0, kept(ev[0])});
    for (int64_t i = en.offset[e]; i < en.offset[e + 1]; ++i)
      c.nodes.push_back({en.nodes[i].t, kept(g.edge_base + i)});
    c.nodes.push_back({1.0, kept(ev[1])});
    for (; l < lattice.size() && std::get<0>(lattice[l]) == e; ++l)
      c.nodes.push_back({std::get<1>(lattice[l]), kept(std::get<2>(lattice[l]))});
    std::sort(c.nodes.begin(), c.nodes.end());
    out.chains.push_back(std::move(c));
  }
  std::sort(out.chains.begin(), out.chains.end(), [](const SharedChain &x, const SharedChain &y) {
    return std::pair(x.lo, x.hi) < std::pair(y.lo, y.hi);
  });
  out.counts = exact_counts(mesh, b);
  split_cell_time(b.totals, time);
  if (arcs) {
    PieceArcGraph &a = *arcs;
    a.set_kept(place.piece, out, kt.nodes);
    for (const SharedChain &c : out.chains)
      for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k)
        a.chain_links.push_back({c.nodes[k].node, c.nodes[k + 1].node});
    a.graph = exact_arc_graph(mesh, en, g, eo, threads);
  }
  return out;
}

ExactCounts sum_counts(const ExactCounts &x, const ExactCounts &y) {
  ExactCounts c;
  c.cells = x.cells + y.cells;
  c.graph_nodes = x.graph_nodes + y.graph_nodes;
  c.edge_critical_points = x.edge_critical_points + y.edge_critical_points;
  c.level_edges = x.level_edges + y.level_edges;
  c.interior_critical_points = x.interior_critical_points + y.interior_critical_points;
  c.connections_direct = x.connections_direct + y.connections_direct;
  c.connections_traced = x.connections_traced + y.connections_traced;
  c.connections_failed = x.connections_failed + y.connections_failed;
  c.descent_steps = x.descent_steps + y.descent_steps;
  c.fallback_cells = x.fallback_cells + y.fallback_cells;
  for (std::size_t r = 0; r < c.fallback_by_reason.size(); ++r)
    c.fallback_by_reason[r] = x.fallback_by_reason[r] + y.fallback_by_reason[r];
  c.fallback_error = std::max(x.fallback_error, y.fallback_error);
  c.unresolved_interior_zeros = x.unresolved_interior_zeros + y.unresolved_interior_zeros;
  c.degenerate_points = x.degenerate_points + y.degenerate_points;
  c.critical_corners = x.critical_corners + y.critical_corners;
  c.critical_curves = x.critical_curves + y.critical_curves;
  c.degenerate_slack = std::max(x.degenerate_slack, y.degenerate_slack);
  return c;
}

PieceTrees merge_piece_trees(const PieceTrees &a, const PieceTrees &b, bool augmented,
                             int threads) {
  if (a.last_piece + 1 != b.first_piece)
    throw std::invalid_argument("merge_piece_trees: the groups are not neighbours");
  PieceTrees out;
  out.first_piece = a.first_piece;
  out.last_piece = b.last_piece;
  // The union of the nodes, in order; a node both hold is one.
  std::vector<int64_t> from_a(a.nodes.size()), from_b(b.nodes.size());
  std::vector<PieceNode> &nodes = out.nodes;
  nodes.reserve(a.nodes.size() + b.nodes.size());
  int64_t shared = 0, shared_edge_nodes = 0;
  std::size_t i = 0, j = 0;
  while (i < a.nodes.size() || j < b.nodes.size()) {
    const bool take_a =
        j == b.nodes.size() || (i < a.nodes.size() && before(a.nodes[i], b.nodes[j]));
    const bool take_b =
        i == a.nodes.size() || (j < b.nodes.size() && before(b.nodes[j], a.nodes[i]));
    if (take_a) {
      from_a[i] = static_cast<int64_t>(nodes.size());
      nodes.push_back(a.nodes[i++]);
    } else if (take_b) {
      from_b[j] = static_cast<int64_t>(nodes.size());
      nodes.push_back(b.nodes[j++]);
    } else { // the same key and value: one node
      const PieceNode m = one_node(a.nodes[i], b.nodes[j]);
      from_a[i++] = from_b[j++] = static_cast<int64_t>(nodes.size());
      nodes.push_back(m);
      ++shared;
      shared_edge_nodes += m.key.kind == NodeKey::EdgeNode;
    }
  }
  for (std::size_t k = 1; k < nodes.size(); ++k)
    if (nodes[k].key == nodes[k - 1].key)
      throw std::logic_error("merge_piece_trees: two pieces give one node different values");
  const int64_t n = static_cast<int64_t>(nodes.size());
  std::vector<GraphEdge> join, split;
  auto add = [](std::vector<GraphEdge> &to, const std::vector<int64_t> &parent,
                const std::vector<int64_t> &map) {
    for (std::size_t k = 0; k < parent.size(); ++k)
      if (parent[k] >= 0)
        to.push_back({map[k], map[static_cast<std::size_t>(parent[k])]});
  };
  add(join, a.join_parent, from_a);
  add(join, b.join_parent, from_b);
  add(split, a.split_parent, from_a);
  add(split, b.split_parent, from_b);
  std::vector<double> values(static_cast<std::size_t>(n));
  std::vector<uint8_t> keep(static_cast<std::size_t>(n));
  std::vector<int64_t> order(static_cast<std::size_t>(n));
  for (int64_t k = 0; k < n; ++k) {
    values[k] = nodes[k].value;
    keep[k] = augmented || !within(nodes[k].span, out.first_piece, out.last_piece);
    order[k] = k;
  }
  // The shared chains of both, an edge's two joined into one: swept once the group has all the
  // edge's cells, else passed on.
  std::vector<SharedChain> chains;
  {
    auto mapped = [](const SharedChain &c, const std::vector<int64_t> &map) {
      SharedChain m = c;
      for (auto &[t, i] : m.nodes)
        i = map[static_cast<std::size_t>(i)];
      return m;
    };
    auto key = [](const SharedChain &c) { return std::pair(c.lo, c.hi); };
    std::size_t i = 0, j = 0;
    while (i < a.chains.size() || j < b.chains.size()) {
      if (j == b.chains.size() || (i < a.chains.size() && key(a.chains[i]) < key(b.chains[j]))) {
        chains.push_back(mapped(a.chains[i++], from_a));
      } else if (i == a.chains.size() || key(b.chains[j]) < key(a.chains[i])) {
        chains.push_back(mapped(b.chains[j++], from_b));
      } else {
        SharedChain m = mapped(a.chains[i++], from_a);
        const SharedChain other = mapped(b.chains[j++], from_b);
        m.nodes.insert(m.nodes.end(), other.nodes.begin(), other.nodes.end());
        std::sort(m.nodes.begin(), m.nodes.end());
        m.nodes.erase(std::unique(m.nodes.begin(), m.nodes.end(),
                                  [](const auto &x, const auto &y) { return x.node == y.node; }),
                      m.nodes.end());
        chains.push_back(std::move(m));
      }
    }
  }
  std::vector<SharedChain> waiting;
  for (SharedChain &c : chains) {
    if (within(c.span, out.first_piece, out.last_piece)) {
      for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) {
        join.push_back({c.nodes[k].node, c.nodes[k + 1].node});
        split.push_back({c.nodes[k].node, c.nodes[k + 1].node});
      }
    } else {
      for (const auto &[t, k] : c.nodes)
        keep[static_cast<std::size_t>(k)] = 1;
      waiting.push_back(std::move(c));
    }
  }
  const KeptMergeTrees kt = sweep_merge_trees(values, {{}, join, split}, keep, threads, order);
  std::vector<PieceNode> kept(kt.nodes.size());
  std::vector<int64_t> new_index(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < kt.nodes.size(); ++k) {
    kept[k] = nodes[kt.nodes[k]];
    new_index[kt.nodes[k]] = static_cast<int64_t>(k);
  }
  for (SharedChain &c : waiting)
    for (auto &[t, k] : c.nodes)
      k = new_index[static_cast<std::size_t>(k)];
  out.chains = std::move(waiting);
  nodes = std::move(kept);
  out.join_parent = kt.join_parent;
  out.split_parent = kt.split_parent;

  out.counts = sum_counts(a.counts, b.counts);
  out.counts.graph_nodes -= shared;
  out.counts.edge_critical_points -= shared_edge_nodes;
  return out;
}

TreeResult tree_of_pieces(const PieceTrees &all, bool augmented, double reference) {
  if (!all.chains.empty())
    throw std::logic_error("tree_of_pieces: edges of cells outside the pieces");
  const int64_t n = static_cast<int64_t>(all.nodes.size());
  std::vector<double> values(static_cast<std::size_t>(n));
  for (int64_t k = 0; k < n; ++k)
    values[k] = all.nodes[k].value;
  std::vector<GraphEdge> join, split;
  for (int64_t k = 0; k < n; ++k) {
    if (all.join_parent[k] >= 0)
      join.push_back({k, all.join_parent[k]});
    if (all.split_parent[k] >= 0)
      split.push_back({k, all.split_parent[k]});
  }
  ContourTree ct = sweep_contour_tree(values, {{}, join, split}, augmented);
  return piece_graph_result(ct, all.counts, augmented, reference,
                            [&](int64_t id) { return all.nodes[id]; });
}

TreeResult piece_graph_result(ContourTree &ct, const ExactCounts &counts, bool augmented,
                              double reference, const std::function<PieceNode(int64_t)> &node) {
  int64_t contracted = 0;
  if (!augmented && counts.fallback_error > 0) {
    std::vector<double> slack(static_cast<std::size_t>(ct.size()));
    for (int64_t i = 0; i < ct.size(); ++i) {
      const PieceNode p = node(ct.nodes[i]);
      slack[i] = p.shared && p.strict ? -1.0 : p.slack; // a certain extremum: no slack
    }
    StandInContraction c = contract_stand_in_arcs(ct, slack);
    if (c.contracted > 0)
      ct = std::move(c.tree);
    contracted = c.contracted;
  }
  TreeResult r = tree_result_of(ct, "exact", augmented, [&](TreeNode &t) {
    const PieceNode p = node(t.graph_node);
    t.cell = p.cell;
    t.uv = p.uv;
    t.location = p.location;
    t.fallback = p.fallback;
    t.position = p.position;
  });
  offset_values(r, reference);
  ExactCounts &c = r.stats.exact.emplace(counts);
  c.fallback_arcs_contracted = contracted;
  return r;
}

PieceNode one_node(const PieceNode &x, const PieceNode &y) {
  PieceNode m = x.order_cell <= y.order_cell ? x : y;
  m.fallback = x.fallback || y.fallback;
  m.slack = std::max(x.slack, y.slack);
  m.strict = x.strict & y.strict;
  return m;
}

} // namespace hoct
