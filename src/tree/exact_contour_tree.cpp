#include "tree/exact_contour_tree.hpp"

#include "cell/edge_nodes.hpp"
#include "cell/sector_connections.hpp"
#include "pl/cell_refinement.hpp"
#include "poly/gradient_zeros.hpp"
#include "poly/lattice.hpp"
#include "tree/contour_tree.hpp"
#include "tree/surface_graph_geometry.hpp"
#include "tree/sweep_contour_tree.hpp"
#include "util/page_pool.hpp"
#include "util/parallel_for.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <tuple>

namespace hoct {
namespace {

using clock_type = std::chrono::steady_clock;
double seconds(clock_type::time_point a, clock_type::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

enum FallbackReason : uint8_t {
  kConstantCell = 1,
  kCriticalCurve = 2,
  kUncertifiedZero = 4,
  kZeroNearBoundary = 8,
  kDegenerateEdge = 16,
  kDegenerateEdgeNode = 32,
  kCertificationFailed = 64,
};

// Where a global node comes from, for positions and reports (trivial: see UninitializedVector).
struct NodeSource {
  int64_t cell;
  Vec2 uv;
  NodeLocation location;
  bool fallback; // in or on a degenerate cell's PL fallback
};

// A graph edge with its geometry (interior polyline points).
struct GeoEdge {
  int64_t a, b;
  std::vector<Vec3> inner;
};

// What the cells of one chunk contribute to the graph. Chunks start on their own cache line:
// neighbouring chunks run on different threads, and their vectors and counters change per cell.
struct alignas(64) CellChunk {
  struct Node {
    int64_t cell;
    Vec2 uv;
    double value;
  };
  UninitializedVector<Node> nodes; // interior critical points of the chunk's cells, in cell order
  // Connections; node refs >= 0 are global ids, -1 - i is the chunk's i-th interior node.
  UninitializedVector<GraphEdge> join, split;
  std::vector<GeoEdge> geo; // with arc geometry: each connection's path (per cell join, split)
  std::vector<int64_t> fallback_cells; // the chunk's cells that fall back, ascending
  int64_t unresolved = 0;              // uncertified interior zeros
  PathCounters counters;
  // Thread time in the two passes over each block of cells (critical points, then connections).
  double critical_seconds = 0, connection_seconds = 0;
};

// Cells per block of the cell loop: a block's critical points are all found before its
// connections, so that each pass is timed once per block, not per cell (a clock read costs
// about as much as a cell without critical points).
constexpr int64_t kCellBlock = 512;

// Per-thread buffers of the cell phase, reused from cell to cell.
struct CellScratch {
  // The block's certified interior critical points, cell by cell (the block's cell i's from
  // critical_first[i] to critical_first[i + 1]).
  std::vector<InteriorCritical> critical;
  int32_t critical_first[kCellBlock + 1];
  // The block's cells that have connections to certify (not falling back, with nodes besides
  // their corners: with only those, every sector lies along an edge), as offsets in the block.
  int32_t to_connect[kCellBlock];
  CellNodes cn;
  std::vector<int> interior_idx;
  std::vector<CellEdgeNode> edge_nodes;
  BernsteinTriangle poly; // the current cell's polynomial (storage reused from cell to cell)
  SectorResult sectors;   // the current cell's connections
};

// The certified connections of regular cell c (its interior critical points: `critical`), a
// cell with nodes besides its corners (with only those, every sector lies along an edge),
// appended with its interior nodes to `out`; or, when a sector cannot be connected, the reason
// for falling back (nothing appended).
uint8_t connect_cell(const Mesh &mesh, const EdgeNodes &en, int64_t c,
                     std::span<const InteriorCritical> critical, bool arc_geometry,
                     CellScratch &scratch, CellChunk &out) {
  const Topology &topo = mesh.topology;
  const Field &field = mesh.field;
  const int64_t edge_base = topo.num_vertices();
  scratch.poly.assign(field.degree(c), field.coefficients(c));
  const BernsteinTriangle &g = scratch.poly;
  CellNodes &cn = scratch.cn;
  cn.nodes.clear();
  scratch.interior_idx.clear();
  scratch.edge_nodes.clear();
  static constexpr double kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (int k = 0; k < 3; ++k) {
    const int64_t v = topo.cell_vertices(c)[k];
    cn.nodes.push_back({{kCorner[k][0], kCorner[k][1]}, field.vertex_value(v), v});
  }
  for (int k = 0; k < 3; ++k) {
    const int64_t e = topo.cell_edge(c, k);
    const bool rev = topo.edge_reversed(c, k);
    auto &chain = cn.chain[k];
    auto &cs = cn.chain_s[k];
    chain.assign(1, k);
    cs.assign(1, 0.0);
    const int64_t n = en.count(e);
    for (int64_t i = 0; i < n; ++i) {
      const int64_t gi = rev ? en.offset[e] + n - 1 - i : en.offset[e] + i;
      const EdgeNode &node = en.nodes[gi];
      const double s = rev ? 1 - node.t : node.t;
      const int idx = static_cast<int>(cn.nodes.size());
      cn.nodes.push_back({point_on_edge(k, s), node.value, edge_base + gi});
      chain.push_back(idx);
      cs.push_back(s);
      scratch.edge_nodes.push_back({k, s, node.second, idx});
    }
    chain.push_back((k + 1) % 3);
    cs.push_back(1.0);
  }
  for (std::size_t i = 0; i < critical.size(); ++i) {
    scratch.interior_idx.push_back(static_cast<int>(cn.nodes.size()));
    cn.nodes.push_back({critical[i].uv, critical[i].value, -1 - static_cast<int64_t>(i)});
  }
  const SectorResult &r = scratch.sectors;
  connect_sectors(g, cn, scratch.interior_idx, scratch.edge_nodes, out.counters, scratch.sectors,
                  arc_geometry);
  if (r.failed || r.degenerate)
    return r.failed ? kCertificationFailed : kDegenerateEdgeNode;
  // The cell's interior node i becomes the chunk's node first + i.
  const int64_t first = static_cast<int64_t>(out.nodes.size());
  for (const InteriorCritical &p : critical)
    out.nodes.push_back({c, p.uv, p.value});
  auto ref = [&](int64_t r) { return r >= 0 ? r : -1 - (first + (-1 - r)); };
  for (auto [a, b] : r.join)
    out.join.push_back({ref(a), ref(b)});
  for (auto [a, b] : r.split)
    out.split.push_back({ref(a), ref(b)});
  if (arc_geometry)
    for (int side = 0; side < 2; ++side) {
      const auto &edges = side == 0 ? r.join : r.split;
      const auto &paths = side == 0 ? r.join_paths : r.split_paths;
      for (std::size_t i = 0; i < edges.size(); ++i) {
        std::vector<Vec3> inner;
        for (std::size_t k = 1; k + 1 < paths[i].size(); ++k)
          inner.push_back(mesh.geometry.position(c, paths[i][k][0], paths[i][k][1]));
        out.geo.push_back({ref(edges[i].first), ref(edges[i].second), std::move(inner)});
      }
    }
  return 0;
}

} // namespace

TreeResult exact_contour_tree(const Mesh &mesh, const ExactTreeOptions &opt) {
  // Large arrays freed by one phase give their pages to the next.
  const PageReuseScope reuse_pages;
  const auto t0 = clock_type::now();
  const Topology &topo = mesh.topology;
  const Field &field = mesh.field;
  const int64_t nv = topo.num_vertices(), ne = topo.num_edges(), nc = topo.num_cells();

  // Edge nodes: once per mesh edge.
  auto report = [&](const char *phase, clock_type::time_point a, clock_type::time_point b) {
    if (opt.progress)
      opt.progress(phase, seconds(a, b));
  };
  EdgeNodeOptions edge_options;
  edge_options.threads = threads_for(ne, thread_count(opt.threads), 2 * opt.cells_per_thread);
  const EdgeNodes en = find_edge_nodes(topo, field, edge_options);
  const int64_t edge_base = nv;
  const auto t1 = clock_type::now();
  report("edge critical points", t0, t1);

  // The cell phase, one pass per cell: interior critical points, degeneracy decisions, and the
  // certified connections of every regular cell. Cells go in fixed contiguous chunks, each
  // collecting its interior nodes and connections in flat buffers; combined in chunk (= cell)
  // order, the result does not depend on the thread count.
  UninitializedVector<uint8_t> fallback; // every cell's entry is written below
  fallback.resize(static_cast<std::size_t>(nc));
  const int threads = threads_for(nc, thread_count(opt.threads), opt.cells_per_thread);
  const int64_t chunks = threads > 1 ? std::min<int64_t>(nc, int64_t{threads} * 16) : 1;
  std::vector<CellChunk> chunk_out(static_cast<std::size_t>(chunks));
  parallel_chunks(nc, chunks, threads, [&](int64_t k, int64_t begin, int64_t end, int) {
    CellChunk &out = chunk_out[k];
    // The cell shape, asked for only when a sliver's reference-triangle search leaves zeros
    // unresolved (find_gradient_zeros then retries in that shape).
    int64_t cell = begin;
    GradientZeroOptions zero_options;
    zero_options.frame = [&] { return mesh.geometry.frame(cell); };
    CellScratch scratch;
    auto block_start = clock_type::now();
    for (int64_t block = begin; block < end; block += kCellBlock) {
      const int64_t block_end = std::min(end, block + kCellBlock);
      // Pass 1: the cells' interior critical points, and which cells fall back.
      scratch.critical.clear();
      int connect_count = 0;
      for (int64_t c = block; c < block_end; ++c) {
        scratch.critical_first[c - block] = static_cast<int32_t>(scratch.critical.size());
        uint8_t why = 0;
        bool edge_nodes_on = false;
        for (int j = 0; j < 3; ++j) {
          const int64_t e = topo.cell_edge(c, j);
          if (en.degeneracy[e] != kEdgeOk)
            why |= kDegenerateEdge;
          edge_nodes_on |= en.count(e) != 0;
        }
        // Most cells: no gradient zero, decided on the stored coefficients.
        const GradientScreen screen = screen_gradient(field.coefficients(c), field.degree(c),
                                                      zero_options.constant_tolerance);
        if (screen.verdict == GradientScreen::kConstant) {
          why |= kConstantCell;
        } else if (screen.verdict != GradientScreen::kNoZero && !(why & kDegenerateEdge)) {
          // (A cell with a degenerate edge falls back whatever its interior holds, and the
          // refinement does not use interior critical points: its zeros are not searched. Next
          // to a plateau such cells are nearly flat, and their searches took half of the tree
          // of 10^4 cells clamped over 30% of the values.)
          scratch.poly.assign(field.degree(c), field.coefficients(c));
          const BernsteinTriangle &g = scratch.poly;
          cell = c;
          const GradientZeros z = find_gradient_zeros(g, zero_options, screen);
          if (z.constant)
            why |= kConstantCell;
          if (z.budget_exhausted)
            why |= kCriticalCurve;
          for (const GradientZero &p : z.zeros) {
            if (!p.certified) {
              why |= kUncertifiedZero;
              ++out.unresolved;
            } else if (p.near_boundary) {
              why |= kZeroNearBoundary;
            } else {
              scratch.critical.push_back({{p.u, p.v}, g(p.u, p.v)});
            }
          }
        }
        fallback[c] = why;
        if (!why &&
            (edge_nodes_on ||
             scratch.critical.size() > static_cast<std::size_t>(scratch.critical_first[c - block])))
          scratch.to_connect[connect_count++] = static_cast<int32_t>(c - block);
      }
      scratch.critical_first[block_end - block] = static_cast<int32_t>(scratch.critical.size());
      const auto critical_done = clock_type::now();
      // Pass 2: the certified connections of the cells that have any.
      for (int n = 0; n < connect_count; ++n) {
        const int32_t i = scratch.to_connect[n];
        const std::span<const InteriorCritical> critical(
            scratch.critical.data() + scratch.critical_first[i],
            static_cast<std::size_t>(scratch.critical_first[i + 1] - scratch.critical_first[i]));
        fallback[block + i] =
            connect_cell(mesh, en, block + i, critical, opt.arc_geometry, scratch, out);
      }
      for (int64_t c = block; c < block_end; ++c)
        if (fallback[c])
          out.fallback_cells.push_back(c);
      const auto block_done = clock_type::now();
      out.critical_seconds += seconds(block_start, critical_done);
      out.connection_seconds += seconds(critical_done, block_done);
      block_start = block_done;
    }
  });
  const auto t3 = clock_type::now();
  report("cells: interior critical points and certified connections", t1, t3);

  // Global ids: vertices, edge nodes, then the interior nodes of regular cells (in cell order),
  // then extra lattice nodes on edges of fallback cells, then fallback cells' sub-vertices.
  std::vector<int64_t> node_base(chunks), join_base(chunks), split_base(chunks);
  int64_t next = edge_base + static_cast<int64_t>(en.nodes.size());
  std::size_t cell_join = 0, cell_split = 0, fallback_count = 0;
  PathCounters counters;
  int64_t unresolved_zeros = 0;
  double critical_seconds = 0, connection_seconds = 0; // thread time, summed over the chunks
  for (int64_t k = 0; k < chunks; ++k) {
    const CellChunk &ch = chunk_out[k];
    node_base[k] = next;
    next += static_cast<int64_t>(ch.nodes.size());
    join_base[k] = static_cast<int64_t>(cell_join);
    cell_join += ch.join.size();
    split_base[k] = static_cast<int64_t>(cell_split);
    cell_split += ch.split.size();
    fallback_count += ch.fallback_cells.size();
    counters.direct += ch.counters.direct;
    counters.traced += ch.counters.traced;
    counters.failed += ch.counters.failed;
    counters.steps += ch.counters.steps;
    unresolved_zeros += ch.unresolved;
    critical_seconds += ch.critical_seconds;
    connection_seconds += ch.connection_seconds;
  }
  const int64_t interior_nodes = next - edge_base - static_cast<int64_t>(en.nodes.size());
  // Large arrays, filled in parallel without being zeroed first.
  // The graph's edges: the cells' lower connections in the join graph only, their upper ones in
  // the split graph only; the edge chains and the fallback cells' sub-edges in both (stored once;
  // the chains listed only with arc geometry).
  UninitializedVector<GraphEdge> join_edges, split_edges, common_edges;
  join_edges.resize(cell_join);
  split_edges.resize(cell_split);

  // Room for the fallback cells' lattice nodes too (at most lattice_size(K) new ones each), so
  // that adding them does not reallocate (and copy) arrays of millions of nodes.
  const int max_degree = std::max(1, field.max_degree());
  const int K = opt.fallback_refinement > 0 ? opt.fallback_refinement : std::max(4, 2 * max_degree);
  const std::size_t fallback_room = fallback_count * static_cast<std::size_t>(lattice_size(K));
  UninitializedVector<double> values;
  values.reserve(static_cast<std::size_t>(next) + fallback_room);
  values.resize(static_cast<std::size_t>(next));
  // Each fallback cell's 3 K^2 sub-edges plus the pieces its lattice nodes add.
  common_edges.reserve(fallback_room / static_cast<std::size_t>(lattice_size(K)) *
                       static_cast<std::size_t>(3 * K * K + 3 * K));
  // Where each node lies: vertices and edge nodes are looked up from the mesh and the edge
  // nodes when asked for (only tree nodes, and graph nodes with arc geometry, ask; an array for
  // millions of graph nodes cost more to fill than its few lookups save), the interior and
  // fallback nodes after them are stored.
  const int64_t tail_base = edge_base + static_cast<int64_t>(en.nodes.size());
  std::vector<NodeSource> tail_source;
  tail_source.reserve(static_cast<std::size_t>(next - tail_base) + fallback_room);
  tail_source.resize(static_cast<std::size_t>(next - tail_base));
  // Vertices and edge nodes of fallback cells: a flag per node id below tail_base (sized at the
  // first fallback cell; a sorted list of the 10^6 marks of a large plateau took 43 ms to sort).
  std::vector<uint8_t> fallback_marked;
  auto mark_fallback = [&](int64_t id) {
    if (fallback_marked.empty())
      fallback_marked.assign(static_cast<std::size_t>(tail_base), 0);
    fallback_marked[static_cast<std::size_t>(id)] = 1;
  };
  // Values of vertices and edge nodes.
  // Threads for the gathering loops: only where each gets enough items to pay for its start.
  // (32,768 items each by default; fewer with the option, as tests use it.)
  auto gather_threads = [&](int64_t items) {
    return threads_for(items, threads, 128 * opt.cells_per_thread);
  };
  parallel_for(nv, gather_threads(nv), [&](int64_t begin, int64_t end, int) {
    for (int64_t v = begin; v < end; ++v) {
      values[v] = field.vertex_value(v);
    }
  });
  const int64_t edge_node_count = static_cast<int64_t>(en.nodes.size());
  parallel_for(edge_node_count, gather_threads(edge_node_count),
               [&](int64_t begin, int64_t end, int) {
                 for (int64_t i = begin; i < end; ++i)
                   values[edge_base + i] = en.nodes[i].value;
               });
  // Interior nodes and the cells' connections in global ids, each chunk into its own slots.
  const int64_t gathered = next - edge_base + static_cast<int64_t>(cell_join + cell_split);
  parallel_for(chunks, gather_threads(gathered), [&](int64_t begin, int64_t end, int) {
    for (int64_t k = begin; k < end; ++k) {
      const CellChunk &ch = chunk_out[k];
      const int64_t base = node_base[k];
      for (std::size_t i = 0; i < ch.nodes.size(); ++i) {
        values[base + i] = ch.nodes[i].value;
        tail_source[base - tail_base + i] = {ch.nodes[i].cell, ch.nodes[i].uv,
                                             NodeLocation::Interior, false};
      }
      auto resolve = [&](const GraphEdge &e) {
        return GraphEdge{e.a >= 0 ? e.a : base + (-1 - e.a), e.b >= 0 ? e.b : base + (-1 - e.b)};
      };
      for (std::size_t i = 0; i < ch.join.size(); ++i)
        join_edges[join_base[k] + i] = resolve(ch.join[i]);
      for (std::size_t i = 0; i < ch.split.size(); ++i)
        split_edges[split_base[k] + i] = resolve(ch.split[i]);
    }
  });
  // Graph edges with their geometry (interior polyline points), when asked for.
  std::vector<GeoEdge> geo_edges;
  for (int64_t k = 0; k < chunks; ++k)
    for (GeoEdge &e : chunk_out[k].geo) {
      const int64_t base = node_base[k];
      geo_edges.push_back({e.a >= 0 ? e.a : base + (-1 - e.a), e.b >= 0 ? e.b : base + (-1 - e.b),
                           std::move(e.inner)});
    }
  // The fallback cells, ascending (chunks are in cell order).
  std::vector<int64_t> fallback_cells;
  fallback_cells.reserve(fallback_count);
  for (const CellChunk &ch : chunk_out)
    fallback_cells.insert(fallback_cells.end(), ch.fallback_cells.begin(), ch.fallback_cells.end());
  chunk_out = {};

  // Fallback cells: k x k refinement through the edge nodes, PL rule (all sub-edges in both
  // graphs). Lattice points on an edge are shared by both cells of the edge.
  std::map<std::pair<int64_t, int>, int64_t> lattice_node; // (edge, step from lo) -> id
  auto add_node = [&](double value, int64_t cell, const Vec2 &uv, NodeLocation loc) {
    values.push_back(value);
    tail_source.push_back({cell, uv, loc, true});
    return next++;
  };
  std::array<int64_t, 8> reason_count{};
  std::array<std::vector<double>, 3> extra;
  std::vector<int64_t> ids;
  for (const int64_t c : fallback_cells) {
    for (int b = 0; b < 7; ++b)
      if (fallback[c] & (1u << b))
        ++reason_count[b];
    // A constant cell is one flat region (DESIGN.md section 7): its boundary, the chains of its
    // three edges (its corners, and the lattice nodes its non-constant neighbours put there), all
    // of its value, already connects it; sub-vertices inside it would only add nodes of that
    // value (on a field clamped over a third of 10^6 cubic cells, 5.2 million of them).
    if (fallback[c] & kConstantCell) {
      for (int k = 0; k < 3; ++k) {
        mark_fallback(topo.cell_vertices(c)[k]);
        const int64_t e = topo.cell_edge(c, k);
        for (int64_t i = 0; i < en.count(e); ++i)
          mark_fallback(edge_base + en.offset[e] + i);
      }
      continue;
    }
    const BernsteinTriangle g = field.cell_polynomial(c);
    // Edge nodes of each local edge (local parameters, ascending), minus lattice coincidences.
    std::array<std::vector<int64_t>, 3> extra_ids;
    std::array<std::map<int, int64_t>, 3> lattice_hits; // local step -> edge node id
    for (int k = 0; k < 3; ++k) {
      const int64_t e = topo.cell_edge(c, k);
      const bool rev = topo.edge_reversed(c, k);
      extra[k].clear();
      const int64_t n = en.count(e);
      for (int64_t i = 0; i < n; ++i) {
        const int64_t gi = rev ? en.offset[e] + n - 1 - i : en.offset[e] + i;
        const double s = rev ? 1 - en.nodes[gi].t : en.nodes[gi].t;
        const double step = std::round(s * K);
        if (std::abs(s * K - step) <= 1e-9 && step > 0 && step < K) {
          lattice_hits[k][static_cast<int>(step)] = edge_base + gi;
          continue;
        }
        extra[k].push_back(s);
        extra_ids[k].push_back(edge_base + gi);
      }
    }
    const CellRefinement cr = refine_cell(K, extra);
    ids.resize(cr.vertices.size());
    for (std::size_t i = 0; i < cr.vertices.size(); ++i) {
      const CellSubVertex &sv = cr.vertices[i];
      switch (sv.kind) {
      case CellSubVertex::Kind::Corner:
        ids[i] = topo.cell_vertices(c)[sv.corner];
        break;
      case CellSubVertex::Kind::EdgeExtra:
        ids[i] = extra_ids[sv.edge][sv.index];
        break;
      case CellSubVertex::Kind::EdgeLattice: {
        auto hit = lattice_hits[sv.edge].find(sv.index);
        if (hit != lattice_hits[sv.edge].end()) {
          ids[i] = hit->second;
          break;
        }
        const int64_t e = topo.cell_edge(c, sv.edge);
        const int step = topo.edge_reversed(c, sv.edge) ? K - sv.index : sv.index;
        auto [it, fresh] = lattice_node.try_emplace({e, step}, -1);
        if (fresh)
          it->second = add_node(field.edge_polynomial(e)(static_cast<double>(step) / K), c,
                                {sv.u, sv.v}, NodeLocation::Edge);
        ids[i] = it->second;
        break;
      }
      case CellSubVertex::Kind::Interior:
        ids[i] = add_node(g(sv.u, sv.v), c, {sv.u, sv.v}, NodeLocation::Interior);
        break;
      }
    }
    for (int64_t id : ids)
      if (id >= tail_base)
        tail_source[id - tail_base].fallback = true;
      else
        mark_fallback(id);
    for (const auto &t : cr.triangles)
      for (int j = 0; j < 3; ++j) {
        common_edges.push_back({ids[t[j]], ids[t[(j + 1) % 3]]});
        if (opt.arc_geometry)
          geo_edges.push_back({ids[t[j]], ids[t[(j + 1) % 3]], {}});
      }
  }

  // Edge chains: consecutive nodes along every edge (vertices, edge nodes, lattice nodes).
  // Fallback cells' lattice nodes by edge (edge, position, id), sorted.
  std::vector<std::tuple<int64_t, double, int64_t>> lattice_on_edge;
  lattice_on_edge.reserve(lattice_node.size());
  for (const auto &[key, id] : lattice_node)
    lattice_on_edge.emplace_back(key.first, static_cast<double>(key.second) / K, id);
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
  std::size_t chain_first = 0;
  int64_t chain_pieces = 0;
  UninitializedVector<int64_t> curved_piece_ids;
  UninitializedVector<EdgePiece> curved_pieces;
  // Without geometry the sweeps walk the edge chains themselves (EdgeChains: no list of their
  // pieces in memory), except on the few edges with fallback lattice nodes, whose chains are
  // listed here and skipped there.
  std::vector<int64_t> listed_chains;
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
      parallel_chunks(
          ne, blocks, gather_threads(ne), [&](int64_t b, int64_t begin, int64_t end, int) {
            std::size_t curved = 0, l = lattice_from(begin);
            for (int64_t e = begin; e < end; ++e) {
              std::size_t n = 1 + static_cast<std::size_t>(en.count(e));
              for (; l < lattice_on_edge.size() && std::get<0>(lattice_on_edge[l]) == e; ++l)
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
        ne, blocks, gather_threads(ne), [&](int64_t b, int64_t begin, int64_t end, int) {
          std::vector<std::pair<double, int64_t>> block_chain;
          std::size_t at = block_first[b], curved = block_curved[b], l = lattice_from(begin);
          for (int64_t e = begin; e < end; ++e) {
            chain_of(e, l, block_chain);
            // Positions along the edge through its first cell.
            const int64_t ec = first_cell(e);
            const bool straight = mesh.geometry.is_linear(ec);
            int ek = 0;
            while (topo.cell_edge(ec, ek) != e)
              ++ek;
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
            throw std::logic_error("exact_contour_tree: edge chain pieces miscounted");
        });
  }
  auto source_of = [&](int64_t id) -> NodeSource {
    if (id >= tail_base)
      return tail_source[id - tail_base];
    const bool marked = !fallback_marked.empty() && fallback_marked[static_cast<std::size_t>(id)];
    if (id < nv)
      return {topo.vertex_cell(id), point_on_edge(topo.vertex_corner(id), 0.0),
              NodeLocation::Vertex, marked};
    // Edge node i of edge e, placed in the edge's first cell.
    const int64_t i = id - edge_base;
    const int64_t e =
        std::upper_bound(en.offset.begin(), en.offset.begin() + ne + 1, i) - en.offset.begin() - 1;
    const int64_t c = topo.edge_cells_begin(e)[0];
    int k = 0;
    while (topo.cell_edge(c, k) != e)
      ++k;
    const double s = topo.edge_reversed(c, k) ? 1 - en.nodes[i].t : en.nodes[i].t;
    return {c, point_on_edge(k, s), NodeLocation::Edge, marked};
  };
  const auto t4 = clock_type::now();
  report("graph assembly: fallback cells and edge chains", t3, t4);

  // Global sweeps and merge (in rank space; the join and the split sweep on a thread each when
  // there are two).
  const int sweep_threads = threads_for(static_cast<int64_t>(values.size()),
                                        thread_count(opt.threads), 8 * opt.cells_per_thread);
  SweepTimings sweep_time;
  SweepEdges sweep_edges{common_edges, join_edges, split_edges};
  if (!opt.arc_geometry)
    sweep_edges.chains = {topo.all_edge_vertices(),
                          std::span<const int64_t>(en.offset.data(), en.offset.size()), edge_base,
                          listed_chains};
  const ContourTree ct =
      sweep_contour_tree(values, sweep_edges, opt.augmented, sweep_threads, &sweep_time);
  if (opt.progress) {
    opt.progress("join and split sweeps", sweep_time.order + sweep_time.sweeps);
    opt.progress("merge", sweep_time.merge);
  }
  const auto t6 = clock_type::now();

  TreeResult r;
  r.method = "exact";
  r.augmented = opt.augmented;
  const auto types = ct.types();
  const auto deg = ct.degrees();
  r.nodes.resize(ct.size());
  for (int64_t i = 0; i < ct.size(); ++i) {
    const int64_t id = ct.nodes[i];
    TreeNode &n = r.nodes[i];
    n.type = types[i];
    n.value = ct.values[i];
    const NodeSource where = source_of(id);
    n.cell = where.cell;
    n.uv = where.uv;
    n.location = where.location;
    n.fallback = where.fallback;
    n.graph_node = id;
    n.position = mesh.geometry.position(n.cell, n.uv[0], n.uv[1]);
    n.up = deg[i][0];
    n.down = deg[i][1];
  }
  r.arcs = ct.arcs;
  r.pairs = tree_pairs(ct);
  if (opt.arc_geometry) {
    // Where each graph node lies (a point of a cell; mapped to the surface when drawn).
    const int64_t graph_nodes = static_cast<int64_t>(values.size());
    UninitializedVector<CellPoint> node_points(values.size());
    parallel_for(graph_nodes, gather_threads(graph_nodes), [&](int64_t begin, int64_t end, int) {
      for (int64_t v = begin; v < end; ++v) {
        const NodeSource where = source_of(v);
        node_points[v] = {where.cell, where.uv[0], where.uv[1]};
      }
    });
    const std::size_t piece_count = static_cast<std::size_t>(chain_pieces);
    auto graph = std::make_shared<GeometricGraph>(
        std::vector<double>(values.begin(), values.end()),
        std::make_shared<const SurfaceGraphGeometry>(mesh.geometry, std::move(node_points),
                                                     chain_pieces, std::move(curved_piece_ids),
                                                     std::move(curved_pieces)));
    // The edge chains' pieces (placed by the graph's geometry), then the cells' connections and
    // the fallback cells' sub-edges with their interior points.
    const std::size_t edges = piece_count + geo_edges.size();
    std::vector<std::array<int64_t, 2>> ends(edges);
    std::vector<int64_t> point_offset(geo_edges.size() + 1, 0);
    parallel_for(chain_pieces, gather_threads(chain_pieces), [&](int64_t begin, int64_t end, int) {
      for (int64_t i = begin; i < end; ++i)
        ends[i] = {common_edges[chain_first + i].a, common_edges[chain_first + i].b};
    });
    std::size_t points = 0;
    for (std::size_t j = 0; j < geo_edges.size(); ++j) {
      ends[piece_count + j] = {geo_edges[j].a, geo_edges[j].b};
      point_offset[j] = static_cast<int64_t>(points);
      points += geo_edges[j].inner.size();
    }
    point_offset[geo_edges.size()] = static_cast<int64_t>(points);
    UninitializedVector<Vec3> inner(points);
    std::size_t at = 0;
    for (const auto &e : geo_edges) {
      std::copy(e.inner.begin(), e.inner.end(), inner.begin() + static_cast<std::ptrdiff_t>(at));
      at += e.inner.size();
    }
    graph->set_edges(std::move(ends), std::move(point_offset), std::move(inner));
    graph->finish();
    r.graph = std::move(graph);
  }
  const auto t7 = clock_type::now();

  r.add_stat("cells", static_cast<double>(nc));
  r.add_stat("graph_nodes", static_cast<double>(values.size()));
  r.add_stat("edge_critical_points", static_cast<double>(en.nodes.size()));
  r.add_stat("interior_critical_points", static_cast<double>(interior_nodes));
  r.add_stat("connections_direct", static_cast<double>(counters.direct));
  r.add_stat("connections_traced", static_cast<double>(counters.traced));
  r.add_stat("connections_failed", static_cast<double>(counters.failed));
  r.add_stat("descent_steps", static_cast<double>(counters.steps));
  r.add_stat("fallback_cells", static_cast<double>(fallback_count));
  static const char *reason_names[7] = {
      "fallback_constant_cell",       "fallback_critical_curve",  "fallback_uncertified_zero",
      "fallback_zero_near_boundary",  "fallback_degenerate_edge", "fallback_degenerate_edge_node",
      "fallback_certification_failed"};
  for (int b = 0; b < 7; ++b)
    r.add_stat(reason_names[b], static_cast<double>(reason_count[b]));
  r.add_stat("unresolved_interior_zeros", static_cast<double>(unresolved_zeros));
  r.add_stat("time_edge_nodes_s", seconds(t0, t1));
  // The cell phase, and its two passes: their shares of its wall time are their shares of the
  // threads' time in them (on one thread, their own times).
  const double cell_seconds = seconds(t1, t3);
  const double passes = critical_seconds + connection_seconds;
  const double critical_share = passes > 0 ? critical_seconds / passes : 0.5;
  r.add_stat("time_cells_s", cell_seconds);
  r.add_stat("time_interior_critical_points_s", cell_seconds * critical_share);
  r.add_stat("time_connections_s", cell_seconds * (1 - critical_share));
  r.add_stat("time_graph_assembly_s", seconds(t3, t4));
  r.add_stat("time_sweeps_s", sweep_time.order + sweep_time.sweeps);
  r.add_stat("time_merge_s", sweep_time.merge);
  r.add_stat("time_output_s", seconds(t6, t7));
  return r;
}

} // namespace hoct
