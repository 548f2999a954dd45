#include "exact/edge_chains.hpp"

#include "exact/graph_assembly.hpp"
#include "poly/reference_triangle.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <stdexcept>

namespace hoct {

void add_edge_chains(const Mesh &mesh, const EdgeNodes &en, const DegenerateCells &degenerate,
                     const ExactTreeOptions &opt, int threads, ExactGraph &g) {
  const Topology &topo = mesh.topology;
  const int64_t ne = topo.num_edges();
  const int64_t edge_base = g.edge_base;
  const auto &lattice_on_edge = degenerate.lattice_on_edge;
  // The chain of edge e (position along the edge, node id), ascending: its vertices, its edge
  // nodes (ascending already) and its lattice nodes (from `lattice`, the edge's first entry in
  // lattice_on_edge, advanced past them).
  auto chain_of = [&](int64_t e, std::size_t &lattice,
                      std::vector<std::pair<double, int64_t>> &chain) {
    chain.clear();
    chain.push_back({0.0, topo.edge_vertices(e)[0]});
    for (int64_t i = en.offset[e]; i < en.offset[e + 1]; ++i)
      chain.push_back({en.nodes[i].t, edge_base + i});
    chain.push_back({1.0, topo.edge_vertices(e)[1]});
    bool extra = false;
    for (; lattice < lattice_on_edge.size() && std::get<0>(lattice_on_edge[lattice]) == e;
         ++lattice, extra = true)
      chain.push_back(
          {std::get<1>(lattice_on_edge[lattice]), std::get<2>(lattice_on_edge[lattice])});
    if (extra)
      std::sort(chain.begin(), chain.end());
  };
  std::vector<std::pair<double, int64_t>> chain;
  // With geometry, the chain pieces are common_edges[chain_first ..] (the geometric graph's
  // first edges); those in curved cells also as pieces of their edges in the edges' first cells,
  // in curved_pieces, by ascending piece number in curved_piece_ids (mapped to the surface only
  // if an arc is drawn through them).
  std::size_t &chain_first = g.chain_first;
  int64_t &chain_pieces = g.chain_pieces;
  UninitializedVector<int64_t> &curved_piece_ids = g.curved_piece_ids;
  UninitializedVector<EdgePiece> &curved_pieces = g.curved_pieces;
  UninitializedVector<GraphEdge> &common_edges = g.common_edges;
  // Without geometry the sweeps walk the edge chains themselves (EdgeChains: no list of their
  // pieces in memory), except on the few edges with fallback lattice nodes, whose chains are
  // listed here and skipped there.
  std::vector<int64_t> &listed_chains = g.listed_chains;
  if (!opt.arc_geometry) {
    for (std::size_t l = 0; l < lattice_on_edge.size();) {
      const int64_t e = std::get<0>(lattice_on_edge[l]);
      chain_of(e, l, chain);
      listed_chains.push_back(e);
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        common_edges.push_back({chain[i].second, chain[i + 1].second});
    }
  } else {
    // With geometry: every chain piece, edge by edge, in fixed blocks of edges on the threads,
    // each written where its pieces go (a block's piece count is known beforehand: an edge's
    // edge nodes and lattice nodes plus one). Only the pieces of curved cells are kept as
    // such: a piece of a straight-sided cell is drawn as the segment between its ends.
    const int64_t blocks = std::max<int64_t>(1, std::min<int64_t>(ne, 256));
    auto lattice_from = [&](int64_t e) { // the first lattice node on edge e or after
      return static_cast<std::size_t>(
          std::lower_bound(lattice_on_edge.begin(), lattice_on_edge.end(), e,
                           [](const auto &x, int64_t edge) { return std::get<0>(x) < edge; }) -
          lattice_on_edge.begin());
    };
    auto first_cell = [&](int64_t e) { return topo.edge_cells_begin(e)[0]; };
    std::vector<std::size_t> block_first(static_cast<std::size_t>(blocks) + 1, 0),
        block_curved(static_cast<std::size_t>(blocks) + 1, 0);
    for (int64_t b = 0; b < blocks; ++b) {
      const int64_t begin = ne * b / blocks, end = ne * (b + 1) / blocks;
      block_first[b + 1] =
          block_first[b] +
          static_cast<std::size_t>(end - begin + en.offset[end] - en.offset[begin]) +
          (lattice_from(end) - lattice_from(begin));
    }
    if (mesh.geometry.curved_cells() > 0)
      parallel_chunks(ne, blocks, gather_threads(ne, threads, opt),
                      [&](int64_t b, int64_t begin, int64_t end, int) {
                        std::size_t curved = 0, l = lattice_from(begin);
                        for (int64_t e = begin; e < end; ++e) {
                          std::size_t n = 1 + static_cast<std::size_t>(en.count(e));
                          for (; l < lattice_on_edge.size() && std::get<0>(lattice_on_edge[l]) == e;
                               ++l)
                            ++n;
                          if (!mesh.geometry.is_linear(first_cell(e)))
                            curved += n;
                        }
                        block_curved[b + 1] = curved;
                      });
    for (int64_t b = 0; b < blocks; ++b)
      block_curved[b + 1] += block_curved[b];
    const std::size_t piece_count = block_first[blocks];
    chain_first = common_edges.size();
    common_edges.resize(chain_first + piece_count);
    chain_pieces = static_cast<int64_t>(piece_count);
    curved_piece_ids.resize(block_curved[blocks]);
    curved_pieces.resize(block_curved[blocks]);
    parallel_chunks(
        ne, blocks, gather_threads(ne, threads, opt),
        [&](int64_t b, int64_t begin, int64_t end, int) {
          std::vector<std::pair<double, int64_t>> block_chain;
          std::size_t at = block_first[b], curved = block_curved[b], l = lattice_from(begin);
          for (int64_t e = begin; e < end; ++e) {
            chain_of(e, l, block_chain);
            // Positions along the edge through its first cell.
            const int64_t ec = first_cell(e);
            const bool straight = mesh.geometry.is_linear(ec);
            const int ek = topo.local_edge(ec, e);
            const bool erev = topo.edge_reversed(ec, ek);
            for (std::size_t i = 0; i + 1 < block_chain.size(); ++i, ++at) {
              common_edges[chain_first + at] = {block_chain[i].second, block_chain[i + 1].second};
              if (straight)
                continue;
              const double t0 = block_chain[i].first, t1 = block_chain[i + 1].first;
              const Vec2 p0 = point_on_edge(ek, erev ? 1 - t0 : t0),
                         p1 = point_on_edge(ek, erev ? 1 - t1 : t1);
              curved_piece_ids[curved] = static_cast<int64_t>(at);
              curved_pieces[curved++] = {ec, p0[0], p0[1], p1[0], p1[1]};
            }
          }
          if (at != block_first[b + 1] || curved != block_curved[b + 1])
            throw std::logic_error("add_edge_chains: edge chain pieces miscounted");
        });
  }
}

} // namespace hoct
