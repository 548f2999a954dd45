#include "exact/reeb_pieces.hpp"

#include "exact/exact_graph_build.hpp"
#include "exact/graph_sweeps.hpp"
#include "exact/piece_keys.hpp"
#include "exact/seam_gluing.hpp"
#include "mesh/cut_surface.hpp"
#include "tree/path_gluing.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace hoct {

PieceTrees reeb_piece(const Mesh &mesh, const PiecePlace &place, const ExactTreeOptions &options,
                      TreeTimings &time) {
  ExactTreeOptions eo = options;
  eo.arc_geometry = false;
  eo.cut = nullptr;
  Stopwatch clock;
  // The piece cut into disks: along its own cut graph, and apart at the points it shares with
  // other pieces (where it may hold several fans).
  const Topology &topo = mesh.topology;
  std::vector<int64_t> open;
  for (int64_t v = 0; v < topo.num_vertices(); ++v)
    if (!within(place.point_span[topo.vertex_point(v)], place.piece, place.piece))
      open.push_back(v);
  const std::vector<int64_t> cuts = cut_graph_edges(topo);
  const CutSurface cut = cut_open(mesh, cuts, open);
  time.cut = clock.lap();

  const Mesh &m = cut.mesh;
  const ExactGraphBuild b = build_exact_graph(m, eo, time);
  const ExactGraph &g = b.graph;
  const PieceKeys keys(m, place, b, lattice_steps(m, eo), &topo, cut.vertex_origin);
  const int64_t n = g.size();
  const int threads = threads_for(n, thread_count(eo.threads), 8 * eo.cells_per_thread);
  const std::vector<int64_t> order = key_order(g.values, keys, threads);
  // What the gluing needs: the seams' nodes (the cut points' copies among them), and the
  // vertices and edge nodes other pieces may hold.
  std::vector<uint8_t> shared = seam_nodes(cut, b.edge_nodes, g.tail_base);
  for (int64_t id = 0; id < g.tail_base; ++id)
    if (!within(keys.span(id), place.piece, place.piece))
      shared[id] = 1;
  std::vector<uint8_t> keep(static_cast<std::size_t>(n), eo.augmented ? 1 : 0);
  if (!eo.augmented)
    std::copy(shared.begin(), shared.end(), keep.begin());
  const KeptMergeTrees kt =
      sweep_merge_trees(g.values, exact_sweep_edges(m, b.edge_nodes, g, eo), keep, threads, order);

  PieceTrees out;
  out.first_piece = out.last_piece = place.piece;
  out.join_parent = kt.join_parent;
  out.split_parent = kt.split_parent;
  out.nodes = piece_nodes(m, place, b, keys, kt.nodes, shared);
  // The chains to glue: both copies of each cut edge, and the edges other pieces may hold.
  std::unordered_map<int64_t, int64_t> index_of;
  for (std::size_t i = 0; i < kt.nodes.size(); ++i)
    index_of[kt.nodes[i]] = static_cast<int64_t>(i);
  const auto kept = [&](int64_t id) {
    const auto it = index_of.find(id);
    if (it == index_of.end())
      throw std::logic_error("reeb_piece: a node of a seam was not kept");
    return it->second;
  };
  const Topology &t = m.topology;
  std::vector<uint8_t> seam(static_cast<std::size_t>(t.num_edges()), 0);
  for (const auto &s : cut.seams)
    seam[s[0]] = seam[s[1]] = 1;
  const EdgeNodes &en = b.edge_nodes;
  for (int64_t e = 0; e < t.num_edges(); ++e) {
    if (!t.is_boundary_edge(e) || (!seam[e] && within(keys.edge_span(e), place.piece, place.piece)))
      continue;
    const auto &ev = t.edge_vertices(e);
    SharedChain c;
    c.lo = keys.point(ev[0]);
    c.hi = keys.point(ev[1]);
    c.span = keys.edge_span(e);
    c.nodes.push_back({0.0, kept(ev[0])});
    for (int64_t i = en.offset[e]; i < en.offset[e + 1]; ++i)
      c.nodes.push_back({en.nodes[i].t, kept(g.edge_base + i)});
    c.nodes.push_back({1.0, kept(ev[1])});
    out.chains.push_back(std::move(c));
  }
  out.counts = exact_counts(m, b);
  count_copies_once(cut, en, out.counts);
  split_cell_time(b.totals, time);
  return out;
}

namespace {

// A piece's node: its piece (index into the pieces) and its index there.
struct Member {
  int64_t piece, index;
};

} // namespace

TreeResult reeb_graph_of_pieces(std::span<const PieceTrees> pieces, bool augmented,
                                double reference) {
  Stopwatch clock;
  const auto node = [&](const Member &m) -> const PieceNode & {
    return pieces[m.piece].nodes[m.index];
  };
  // Every piece's kept nodes in the whole's total order (value, key); a point's copies (one key)
  // next to each other, by piece and index.
  std::vector<Member> all;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (std::size_t i = 0; i < pieces[p].nodes.size(); ++i)
      all.push_back({static_cast<int64_t>(p), static_cast<int64_t>(i)});
  std::sort(all.begin(), all.end(), [&](const Member &x, const Member &y) {
    const PieceNode &a = node(x), &b = node(y);
    if (a.value != b.value)
      return a.value < b.value;
    if (a.key != b.key)
      return a.key < b.key;
    return x.piece < y.piece || (x.piece == y.piece && x.index < y.index);
  });
  const int64_t n = static_cast<int64_t>(all.size());
  std::vector<std::vector<int64_t>> id_of(pieces.size());
  for (std::size_t p = 0; p < pieces.size(); ++p)
    id_of[p].resize(pieces[p].nodes.size());
  ContourTree disks;
  disks.nodes.resize(static_cast<std::size_t>(n));
  disks.values.resize(static_cast<std::size_t>(n));
  for (int64_t k = 0; k < n; ++k) {
    id_of[all[k].piece][all[k].index] = k;
    disks.nodes[k] = k;
    disks.values[k] = node(all[k]).value;
  }
  // Each piece's disks' contour trees (every kept node in them), as arcs between all nodes.
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const PieceTrees &piece = pieces[p];
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
    const ContourTree forest = sweep_contour_tree(values, {{}, join, split}, true);
    for (const auto &[a, b] : forest.arcs) {
      const int64_t x = id_of[p][forest.nodes[a]], y = id_of[p][forest.nodes[b]];
      disks.arcs.push_back({std::min(x, y), std::max(x, y)});
    }
  }

  // The gluing: a point's copies (nodes of one key: vertices, edge nodes, the fallback lattice's
  // nodes on edges) are one; each cut edge's and each shared edge's two chains are one curve,
  // segment by segment.
  PathGluing gluing;
  std::vector<int64_t> run_start(static_cast<std::size_t>(n)), run_end(static_cast<std::size_t>(n));
  int64_t repeated_nodes = 0, repeated_edge_nodes = 0;
  for (int64_t k = 0; k < n;) {
    int64_t j = k + 1;
    while (j < n && node(all[j]).key == node(all[k]).key)
      ++j;
    for (int64_t i = k; i < j; ++i) {
      run_start[i] = k;
      run_end[i] = j;
    }
    if (j - k > 1) {
      for (int64_t i = k; i < j; ++i)
        gluing.group_members.push_back(i);
      gluing.group_offset.push_back(static_cast<int64_t>(gluing.group_members.size()));
      // Counted once: the other pieces' copies (each piece counted its own once).
      int64_t holders = 1;
      for (int64_t i = k + 1; i < j; ++i)
        holders += all[i].piece != all[i - 1].piece;
      repeated_nodes += holders - 1;
      if (node(all[k]).key.kind == NodeKey::EdgeNode)
        repeated_edge_nodes += holders - 1;
    }
    k = j;
  }
  struct ChainRef {
    int64_t lo, hi, piece, index;
  };
  std::vector<ChainRef> chains;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (std::size_t c = 0; c < pieces[p].chains.size(); ++c)
      chains.push_back({pieces[p].chains[c].lo, pieces[p].chains[c].hi, static_cast<int64_t>(p),
                        static_cast<int64_t>(c)});
  std::sort(chains.begin(), chains.end(), [](const ChainRef &x, const ChainRef &y) {
    return std::tie(x.lo, x.hi, x.piece, x.index) < std::tie(y.lo, y.hi, y.piece, y.index);
  });
  int64_t seam_edges = 0;
  for (std::size_t i = 0; i < chains.size();) {
    std::size_t j = i + 1;
    while (j < chains.size() && chains[j].lo == chains[i].lo && chains[j].hi == chains[i].hi)
      ++j;
    if (j - i > 2)
      throw std::logic_error("reeb_graph_of_pieces: an edge with more than two sides");
    if (j - i == 2) { // (one chain alone: an edge of the whole's boundary)
      const SharedChain &a = pieces[chains[i].piece].chains[chains[i].index];
      const SharedChain &b = pieces[chains[i + 1].piece].chains[chains[i + 1].index];
      if (a.nodes.size() != b.nodes.size())
        throw std::logic_error("reeb_graph_of_pieces: the two sides of an edge have different "
                               "edge nodes");
      const auto id = [&](const ChainRef &r, const ChainNode &c) { return id_of[r.piece][c.node]; };
      for (std::size_t k = 0; k + 1 < a.nodes.size(); ++k) {
        const int64_t a0 = id(chains[i], a.nodes[k]), a1 = id(chains[i], a.nodes[k + 1]);
        const int64_t b0 = id(chains[i + 1], b.nodes[k]), b1 = id(chains[i + 1], b.nodes[k + 1]);
        if (a0 < a1) // each piece rises in the total order (the ids follow it)
          gluing.paths.push_back({a0, a1, b0, b1});
        else
          gluing.paths.push_back({a1, a0, b1, b0});
      }
      ++seam_edges;
    }
    i = j;
  }
  GluedGraph glued = glue_paths(disks, gluing, !augmented);
  ContourTree &ct = glued.graph;

  // A glued node is its key's copies, as one (one_node).
  const auto merged = [&](int64_t k) {
    PieceNode m = node(all[run_start[k]]);
    for (int64_t i = run_start[k] + 1; i < run_end[k]; ++i)
      m = one_node(m, node(all[i]));
    return m;
  };
  ExactCounts counts;
  for (const PieceTrees &p : pieces)
    counts = sum_counts(counts, p.counts);
  counts.graph_nodes -= repeated_nodes;
  counts.edge_critical_points -= repeated_edge_nodes;
  TreeResult r = piece_graph_result(ct, counts, augmented, reference, merged);
  r.reeb_graph = true;
  r.loops = graph_loops(ct);
  r.stats.seam_edges = seam_edges;
  r.stats.seam_paths_nonmonotone = glued.nonmonotone_paths;
  r.stats.time.gluing = clock.seconds();
  return r;
}

} // namespace hoct
