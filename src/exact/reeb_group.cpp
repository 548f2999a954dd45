#include "exact/reeb_group.hpp"

#include "exact/piece_keys.hpp"
#include "tree/path_gluing.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/stopwatch.hpp"

#include <algorithm>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace hoct {
namespace {

bool below(const PieceNode &x, const PieceNode &y) {
  return std::tie(x.value, x.key) < std::tie(y.value, y.key);
}

ContourTree graph_of(const ReebGroup &g) {
  ContourTree f;
  f.nodes.resize(g.nodes.size());
  std::iota(f.nodes.begin(), f.nodes.end(), int64_t{0});
  f.values.resize(g.nodes.size());
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    f.values[i] = g.nodes[i].value;
  f.arcs = g.arcs;
  return f;
}

std::vector<int64_t> route(const ReebChain &c, std::size_t k) {
  return {c.route_arcs.begin() + c.route_first[k], c.route_arcs.begin() + c.route_first[k + 1]};
}

// Each chain's routes rewritten by `image` (an arc's arcs now, in order), consecutive repeats
// (an arc and the arc it was spliced into) once.
void map_routes(std::vector<ReebChain> &chains,
                const std::function<void(int64_t, std::vector<int64_t> &)> &image) {
  for (ReebChain &c : chains) {
    std::vector<int64_t> first{0}, arcs;
    for (std::size_t k = 0; k + 1 < c.route_first.size(); ++k) {
      const std::size_t start = arcs.size();
      for (int64_t i = c.route_first[k]; i < c.route_first[k + 1]; ++i)
        image(c.route_arcs[i], arcs);
      arcs.erase(std::unique(arcs.begin() + static_cast<std::ptrdiff_t>(start), arcs.end()),
                 arcs.end());
      first.push_back(static_cast<int64_t>(arcs.size()));
    }
    c.route_first = std::move(first);
    c.route_arcs = std::move(arcs);
  }
}

// The edges the group now holds whole: their two sides' segments, to glue (each from its lower
// end, with both routes). The chains of edges still shared stay. An edge with one side is on
// the whole's boundary.
void pair_chains(ReebGroup &g, PathGluing &gluing) {
  std::vector<ReebChain> open;
  std::vector<ReebChain> &c = g.chains;
  for (std::size_t i = 0; i < c.size();) {
    std::size_t j = i + 1;
    while (j < c.size() && c[j].lo == c[i].lo && c[j].hi == c[i].hi)
      ++j;
    if (!within(c[i].span, g.first_piece, g.last_piece)) {
      for (std::size_t k = i; k < j; ++k)
        open.push_back(std::move(c[k]));
      i = j;
      continue;
    }
    if (j - i > 2)
      throw std::logic_error("reeb_group: an edge with more than two sides");
    if (j - i == 2) {
      const ReebChain &a = c[i], &b = c[i + 1];
      if (a.nodes.size() != b.nodes.size())
        throw std::logic_error("reeb_group: the two sides of an edge have different edge nodes");
      for (std::size_t k = 0; k < a.nodes.size(); ++k)
        if (g.nodes[a.nodes[k]].key != g.nodes[b.nodes[k]].key)
          throw std::logic_error("reeb_group: the two sides of an edge have different nodes");
      for (std::size_t k = 0; k + 1 < a.nodes.size(); ++k) {
        if (!a.rising[k] || !b.rising[k]) {
          ++g.nonmonotone; // glued at its ends only (one key each)
          continue;
        }
        const int64_t a0 = a.nodes[k], a1 = a.nodes[k + 1], b0 = b.nodes[k], b1 = b.nodes[k + 1];
        // The indices follow the total order, and both sides have the same keys.
        if (a0 < a1)
          gluing.paths.push_back({a0, a1, b0, b1});
        else
          gluing.paths.push_back({a1, a0, b1, b0});
        gluing.routes.push_back({route(a, k), route(b, k)});
      }
      ++g.seam_edges;
    }
    i = j;
  }
  c = std::move(open);
}

// The graph with its regular nodes spliced out but those kept: each node's new index (-1 if
// spliced), each arc's (the arc it became part of).
struct Spliced {
  ContourTree graph;
  std::vector<int64_t> node_at, arc_at;
};

Spliced splice(const ContourTree &g, const std::vector<uint8_t> &keep) {
  const int64_t n = g.size(), m = static_cast<int64_t>(g.arcs.size());
  std::vector<int32_t> down(static_cast<std::size_t>(n), 0), up(static_cast<std::size_t>(n), 0);
  std::vector<std::array<int64_t, 2>> through(static_cast<std::size_t>(n), {-1, -1});
  for (int64_t a = 0; a < m; ++a) {
    ++up[g.arcs[a][0]];
    ++down[g.arcs[a][1]];
    through[g.arcs[a][1]][0] = a; // a regular node's arc below
    through[g.arcs[a][0]][1] = a; // and above
  }
  const auto regular = [&](int64_t i) { return down[i] == 1 && up[i] == 1 && !keep[i]; };
  Spliced s;
  s.node_at.assign(static_cast<std::size_t>(n), -1);
  for (int64_t i = 0; i < n; ++i)
    if (!regular(i)) {
      s.node_at[i] = s.graph.size();
      s.graph.nodes.push_back(g.nodes[i]);
      s.graph.values.push_back(g.values[i]);
    }
  // From each kept node, each arc up through regular nodes to the next kept node.
  s.arc_at.assign(static_cast<std::size_t>(m), -1);
  std::vector<std::array<int64_t, 2>> arcs;
  for (int64_t a = 0; a < m; ++a) {
    if (regular(g.arcs[a][0]))
      continue;
    int64_t at = a;
    s.arc_at[at] = static_cast<int64_t>(arcs.size());
    while (regular(g.arcs[at][1])) {
      at = through[g.arcs[at][1]][1];
      s.arc_at[at] = static_cast<int64_t>(arcs.size());
    }
    arcs.push_back({s.node_at[g.arcs[a][0]], s.node_at[g.arcs[at][1]]});
  }
  const std::vector<int64_t> rank = sort_arcs(arcs);
  s.graph.arcs = std::move(arcs);
  for (int64_t &a : s.arc_at) {
    if (a < 0)
      throw std::logic_error("reeb_group: a loop of regular nodes");
    a = rank[a];
  }
  return s;
}

// Glues all the group holds (a point's nodes, the edges it holds whole) and reduces it to what
// later groups need: the nodes of points other groups hold and of the chains still open.
void settle(ReebGroup &g, bool augmented) {
  const int64_t n = static_cast<int64_t>(g.nodes.size());
  PathGluing gluing;
  pair_chains(g, gluing);
  for (int64_t k = 0; k < n;) {
    int64_t e = k + 1;
    while (e < n && g.nodes[e].key == g.nodes[k].key)
      ++e;
    if (e - k > 1) {
      for (int64_t i = k; i < e; ++i)
        gluing.group_members.push_back(i);
      gluing.group_offset.push_back(static_cast<int64_t>(gluing.group_members.size()));
    }
    k = e;
  }
  ContourTree graph = graph_of(g);
  std::vector<int64_t> to(static_cast<std::size_t>(n));
  std::iota(to.begin(), to.end(), int64_t{0});
  if (!gluing.paths.empty() || !gluing.group_members.empty()) {
    GluedGraph glued = glue_paths(graph, gluing, false);
    if (glued.nonmonotone_paths > 0) // each rose in its piece's disks: so does its image
      throw std::logic_error("reeb_group: a route that rose no longer rises");
    graph = std::move(glued.graph);
    std::vector<PieceNode> nodes(static_cast<std::size_t>(graph.size()));
    std::vector<uint8_t> seen(nodes.size(), 0);
    for (int64_t i = 0; i < n; ++i) {
      const int64_t x = glued.node_of[i];
      nodes[x] = seen[x] ? one_node(nodes[x], g.nodes[i]) : g.nodes[i];
      seen[x] = 1;
      to[i] = x;
    }
    g.nodes = std::move(nodes);
    std::iota(graph.nodes.begin(), graph.nodes.end(), int64_t{0});
    map_routes(g.chains, [&](int64_t a, std::vector<int64_t> &out) {
      out.insert(out.end(), glued.arc_image[a].begin(), glued.arc_image[a].end());
    });
  }
  for (ReebChain &c : g.chains)
    for (int64_t &i : c.nodes)
      i = to[i];

  const int64_t m = graph.size();
  std::vector<uint8_t> keep(static_cast<std::size_t>(m), augmented ? 1 : 0);
  for (int64_t x = 0; x < m && !augmented; ++x)
    keep[x] = !within(g.nodes[x].span, g.first_piece, g.last_piece);
  for (const ReebChain &c : g.chains)
    for (const int64_t i : c.nodes)
      keep[i] = 1;
  const Spliced s = splice(graph, keep);
  std::vector<PieceNode> kept(static_cast<std::size_t>(s.graph.size()));
  for (int64_t k = 0; k < s.graph.size(); ++k)
    kept[k] = g.nodes[s.graph.nodes[k]];
  for (ReebChain &c : g.chains)
    for (int64_t &i : c.nodes)
      i = s.node_at[i];
  map_routes(g.chains, [&](int64_t a, std::vector<int64_t> &out) { out.push_back(s.arc_at[a]); });
  g.nodes = std::move(kept);
  g.arcs = s.graph.arcs;
}

} // namespace

ReebGroup reeb_group(const PieceTrees &piece, bool augmented) {
  std::vector<ReebChain> chains;
  for (const SharedChain &c : piece.chains) {
    ReebChain r;
    r.lo = {NodeKey::Vertex, c.lo, 0, 0};
    r.hi = {NodeKey::Vertex, c.hi, 0, 0};
    r.span = c.span;
    for (const ChainNode &k : c.nodes)
      r.nodes.push_back(k.node);
    chains.push_back(std::move(r));
  }
  return reeb_group(piece, std::move(chains), augmented);
}

ReebGroup reeb_group(const PieceTrees &piece, std::vector<ReebChain> chains, bool augmented) {
  ReebGroup g;
  g.first_piece = piece.first_piece;
  g.last_piece = piece.last_piece;
  g.nodes = piece.nodes;
  g.counts = piece.counts;
  const int64_t m = static_cast<int64_t>(piece.nodes.size());
  std::vector<double> values(static_cast<std::size_t>(m));
  std::vector<GraphEdge> join, split;
  for (int64_t k = 0; k < m; ++k) {
    values[k] = piece.nodes[k].value;
    if (piece.join_parent[k] >= 0)
      join.push_back({k, piece.join_parent[k]});
    if (piece.split_parent[k] >= 0)
      split.push_back({k, piece.split_parent[k]});
  }
  // The piece's disks' contour forest on every kept node.
  const ContourTree forest = sweep_contour_tree(values, {{}, join, split}, true);
  for (const auto &[a, b] : forest.arcs) {
    const int64_t x = forest.nodes[a], y = forest.nodes[b];
    g.arcs.push_back({std::min(x, y), std::max(x, y)});
  }
  std::sort(g.arcs.begin(), g.arcs.end());
  // Its chains: each segment's path in the disks, and whether it rises.
  std::vector<std::array<int64_t, 2>> ends;
  for (const ReebChain &c : chains)
    for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k)
      ends.push_back({std::min(c.nodes[k], c.nodes[k + 1]), std::max(c.nodes[k], c.nodes[k + 1])});
  const std::vector<std::vector<int64_t>> paths = forest_paths(graph_of(g), ends);
  std::size_t s = 0;
  for (ReebChain &r : chains) {
    r.rising.clear();
    r.route_first.assign(1, 0);
    r.route_arcs.clear();
    for (std::size_t k = 0; k + 1 < r.nodes.size(); ++k, ++s) {
      int64_t at = ends[s][0];
      bool rising = true;
      for (const int64_t a : paths[s]) {
        const int64_t next = g.arcs[a][0] == at ? g.arcs[a][1] : g.arcs[a][0];
        rising = rising && !below(g.nodes[next], g.nodes[at]);
        at = next;
      }
      r.rising.push_back(rising);
      if (rising)
        r.route_arcs.insert(r.route_arcs.end(), paths[s].begin(), paths[s].end());
      r.route_first.push_back(static_cast<int64_t>(r.route_arcs.size()));
    }
  }
  g.chains = std::move(chains);
  std::stable_sort(g.chains.begin(), g.chains.end(), [](const ReebChain &x, const ReebChain &y) {
    return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
  });
  settle(g, augmented);
  return g;
}

ReebGroup merge_reeb_groups(const ReebGroup &a, const ReebGroup &b, bool augmented) {
  if (a.last_piece + 1 != b.first_piece)
    throw std::logic_error("merge_reeb_groups: groups that are not consecutive");
  ReebGroup g;
  g.first_piece = a.first_piece;
  g.last_piece = b.last_piece;
  // Both groups' nodes in one order (value, key), a's first of a key both hold.
  const std::size_t na = a.nodes.size(), nb = b.nodes.size();
  std::vector<int64_t> ia(na), ib(nb);
  g.nodes.reserve(na + nb);
  int64_t both = 0, both_edge_nodes = 0;
  for (std::size_t i = 0, j = 0; i < na || j < nb;) {
    const bool take_a = j == nb || (i < na && !below(b.nodes[j], a.nodes[i]));
    if (take_a && j < nb && a.nodes[i].key == b.nodes[j].key) {
      ++both; // counted once (each group holds one node per key)
      both_edge_nodes += a.nodes[i].key.kind == NodeKey::EdgeNode;
    }
    if (take_a) {
      ia[i] = static_cast<int64_t>(g.nodes.size());
      g.nodes.push_back(a.nodes[i++]);
    } else {
      ib[j] = static_cast<int64_t>(g.nodes.size());
      g.nodes.push_back(b.nodes[j++]);
    }
  }
  for (const auto &[x, y] : a.arcs)
    g.arcs.push_back({ia[x], ia[y]});
  for (const auto &[x, y] : b.arcs)
    g.arcs.push_back({ib[x], ib[y]});
  // The arcs in order (a's, then b's), and where each went.
  const std::vector<int64_t> rank = sort_arcs(g.arcs);
  const std::vector<int64_t> arc_a(rank.begin(), rank.begin() + std::ssize(a.arcs)),
      arc_b(rank.begin() + std::ssize(a.arcs), rank.end());
  std::size_t i = 0, j = 0;
  while (i < a.chains.size() || j < b.chains.size()) {
    const bool take_a = j == b.chains.size() ||
                        (i < a.chains.size() && std::tie(a.chains[i].lo, a.chains[i].hi) <=
                                                    std::tie(b.chains[j].lo, b.chains[j].hi));
    ReebChain c = take_a ? a.chains[i++] : b.chains[j++];
    for (int64_t &x : c.nodes)
      x = (take_a ? ia : ib)[x];
    for (int64_t &x : c.route_arcs)
      x = (take_a ? arc_a : arc_b)[x];
    g.chains.push_back(std::move(c));
  }
  g.counts = sum_counts(a.counts, b.counts);
  g.counts.graph_nodes -= both;
  g.counts.edge_critical_points -= both_edge_nodes;
  g.seam_edges = a.seam_edges + b.seam_edges;
  g.nonmonotone = a.nonmonotone + b.nonmonotone;
  settle(g, augmented);
  return g;
}

TreeResult reeb_graph_of_group(const ReebGroup &all, bool augmented, double reference) {
  Stopwatch clock;
  if (!all.chains.empty())
    throw std::logic_error("reeb_graph_of_group: edges left unglued");
  ContourTree ct = graph_of(all);
  if (!augmented)
    ct = reduce(ct);
  TreeResult r = piece_graph_result(ct, all.counts, augmented, reference,
                                    [&](int64_t k) { return all.nodes[k]; });
  r.reeb_graph = true;
  r.loops = graph_loops(ct);
  r.stats.seam_edges = all.seam_edges;
  r.stats.seam_paths_nonmonotone = all.nonmonotone;
  r.stats.time.gluing = clock.seconds();
  return r;
}

} // namespace hoct
