#include "exact/reeb_pieces.hpp"

#include "exact/exact_arc_graph.hpp"
#include "exact/exact_graph_build.hpp"
#include "exact/graph_sweeps.hpp"
#include "exact/piece_arcs.hpp"
#include "exact/piece_keys.hpp"
#include "exact/seam_gluing.hpp"
#include "mesh/cut_surface.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace hoct {

PieceTrees reeb_piece(const Mesh &mesh, const PiecePlace &place, const ExactTreeOptions &options,
                      TreeTimings &time, PieceArcGraph *arcs) {
  ExactTreeOptions eo = options;
  eo.arc_geometry = arcs != nullptr; // (the sweeps then take the chains' listed pieces)
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
  ExactGraphBuild b = build_exact_graph(m, eo, time);
  ExactGraph &g = b.graph;
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
  if (arcs) {
    // The copies of one point are one point of the surface: a link in the graph too.
    PieceArcGraph &a = *arcs;
    a.set_kept(place.piece, out, kt.nodes);
    std::vector<std::array<int64_t, 2>> links;
    for (const auto &[u, v] : a.chain_links)
      links.push_back({a.ids[u], a.ids[v]});
    a.graph = exact_arc_graph(m, b.edge_nodes, g, eo, threads, links);
  }
  return out;
}

} // namespace hoct
