#include "mesh/topology.hpp"

#include "poly/lattice.hpp"
#include "util/concurrent_sets.hpp"
#include "util/parallel_for.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <atomic>
#include <sstream>

namespace hoct {
namespace {

// A cell's edge, in the bucket of its lower vertex: the higher vertex, then 3 cell + local edge
// (the order of the records in a bucket: by higher vertex, then cell, then local edge).
struct EdgeRecord {
  int64_t hi, cell_local;
  bool operator<(const EdgeRecord &o) const {
    return hi < o.hi || (hi == o.hi && cell_local < o.cell_local);
  }
};

} // namespace

int64_t Topology::neighbor(int64_t c, int k) const {
  const int64_t e = cell_edges_[c][k];
  if (edge_cell_count(e) != 2)
    return -1;
  const int64_t *cells = edge_cells_begin(e);
  return cells[0] == c ? cells[1] : cells[0];
}

Topology Topology::build(const MeshInput &in, ProblemLog &problems, int threads,
                         std::span<const uint8_t> open_points) {
  Topology t;
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  const int64_t np = static_cast<int64_t>(in.num_points());
  const int cell_threads = threads_for(nc, threads, 32768);
  const bool shared = cell_threads > 1; // counters touched by several threads: atomic updates
  auto add_one = [shared](int64_t &x) {
    if (shared)
      std::atomic_ref<int64_t>(x).fetch_add(1, std::memory_order_relaxed);
    else
      ++x;
  };
  auto corner_point = [&](int64_t c, int k) {
    return in.cell_nodes[in.cell_offsets[c] + corner_index(in.cell_degree[c], k)];
  };

  // Vertices: the distinct corner points, numbered in order of first appearance by point index.
  UninitializedVector<int64_t> point_vertex(static_cast<std::size_t>(np));
  {
    PooledVector<uint8_t> corner(static_cast<std::size_t>(np), 0);
    parallel_for(nc, cell_threads, [&](int64_t begin, int64_t end, int) {
      for (int64_t c = begin; c < end; ++c)
        for (int k = 0; k < 3; ++k)
          std::atomic_ref<uint8_t>(corner[corner_point(c, k)]).store(1, std::memory_order_relaxed);
    });
    // Numbered by blocks of points: counts, their prefix sums, then the ids.
    const int64_t blocks = problem_blocks(np);
    std::vector<int64_t> first(static_cast<std::size_t>(blocks) + 1, 0);
    const int point_threads = threads_for(np, threads, 65536);
    parallel_chunks(np, blocks, point_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
      first[b + 1] = std::count(corner.begin() + begin, corner.begin() + end, uint8_t{1});
    });
    for (int64_t b = 0; b < blocks; ++b)
      first[b + 1] += first[b];
    t.vertex_point_.resize(static_cast<std::size_t>(first[blocks]));
    parallel_chunks(np, blocks, point_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
      int64_t next = first[b];
      for (int64_t p = begin; p < end; ++p)
        if (corner[p]) {
          point_vertex[p] = next;
          t.vertex_point_[next++] = p;
        } else {
          point_vertex[p] = -1;
        }
    });
  }
  const int64_t nv = t.num_vertices();

  t.cell_vertices_.resize(nc);
  {
    const int64_t cell_blocks = problem_blocks(nc);
    BlockProblems repeated(cell_blocks);
    parallel_chunks(nc, cell_blocks, cell_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
      for (int64_t c = begin; c < end; ++c) {
        const int64_t corner[3] = {corner_point(c, 0), corner_point(c, 1), corner_point(c, 2)};
        auto &v = t.cell_vertices_[c];
        for (int k = 0; k < 3; ++k)
          v[k] = point_vertex[corner[k]];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
          std::ostringstream m;
          m << "cell " << c << " uses the same corner point twice (points " << corner[0] << ", "
            << corner[1] << ", " << corner[2] << ")";
          repeated[b].add(Problem::RepeatedCorner, m.str());
        }
      }
    });
    repeated.append_to(problems);
  }
  UninitializedVector<int64_t>().swap(point_vertex);

  // Each vertex's lowest-id cell (and, as a cell meets it once unless degenerate, its last
  // corner there).
  t.vertex_cell_.resize(static_cast<std::size_t>(nv));
  parallel_for(nv, threads_for(nv, threads, 65536), [&](int64_t begin, int64_t end, int) {
    std::fill(t.vertex_cell_.begin() + begin, t.vertex_cell_.begin() + end, nc);
  });
  parallel_for(nc, cell_threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t c = begin; c < end; ++c)
      for (int k = 0; k < 3; ++k) {
        int64_t &slot = t.vertex_cell_[t.cell_vertices_[c][k]];
        if (!shared) {
          slot = std::min(slot, c);
          continue;
        }
        std::atomic_ref<int64_t> lowest(slot);
        for (int64_t seen = lowest.load(std::memory_order_relaxed);
             c < seen && !lowest.compare_exchange_weak(seen, c, std::memory_order_relaxed);)
          ;
      }
  });
  t.vertex_corner_.resize(static_cast<std::size_t>(nv));
  parallel_for(nc, cell_threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t c = begin; c < end; ++c)
      for (int k = 0; k < 3; ++k)
        if (t.vertex_cell_[t.cell_vertices_[c][k]] == c)
          t.vertex_corner_[t.cell_vertices_[c][k]] = static_cast<int8_t>(k);
  });

  // Edges: (lo, hi, cell, local) records in that order, bucketed by lo (a counting sort; the
  // order within a bucket does not matter, as it is sorted next) and each bucket (a vertex's few
  // edges) sorted.
  PooledVector<int64_t> bucket(static_cast<std::size_t>(nv) + 1, 0);
  parallel_for(nc, cell_threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t c = begin; c < end; ++c)
      for (int k = 0; k < 3; ++k)
        add_one(bucket[std::min(t.cell_vertices_[c][k], t.cell_vertices_[c][(k + 1) % 3]) + 1]);
  });
  for (int64_t v = 0; v < nv; ++v)
    bucket[v + 1] += bucket[v];
  UninitializedVector<EdgeRecord> rec(static_cast<std::size_t>(3 * nc));
  {
    UninitializedVector<int64_t> fill(static_cast<std::size_t>(nv));
    parallel_for(nv, threads_for(nv, threads, 65536), [&](int64_t begin, int64_t end, int) {
      std::copy(bucket.begin() + begin, bucket.begin() + end, fill.begin() + begin);
    });
    parallel_for(nc, cell_threads, [&](int64_t begin, int64_t end, int) {
      for (int64_t c = begin; c < end; ++c)
        for (int k = 0; k < 3; ++k) {
          const int64_t a = t.cell_vertices_[c][k], b = t.cell_vertices_[c][(k + 1) % 3];
          int64_t &at = fill[std::min(a, b)];
          const int64_t i =
              shared ? std::atomic_ref<int64_t>(at).fetch_add(1, std::memory_order_relaxed) : at++;
          rec[i] = {std::max(a, b), 3 * c + k};
        }
    });
  }
  // Blocks of vertices (their buckets): sorted, and their distinct edges counted, then numbered.
  const int64_t vblocks = problem_blocks(nv);
  const int vertex_threads = threads_for(nv, threads, 16384);
  std::vector<int64_t> edge_first(static_cast<std::size_t>(vblocks) + 1, 0);
  parallel_chunks(nv, vblocks, vertex_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
    int64_t edges = 0;
    for (int64_t v = begin; v < end; ++v) {
      std::sort(rec.begin() + bucket[v], rec.begin() + bucket[v + 1]);
      for (int64_t i = bucket[v]; i < bucket[v + 1]; ++i)
        edges += i == bucket[v] || rec[i].hi != rec[i - 1].hi;
    }
    edge_first[b + 1] = edges;
  });
  for (int64_t b = 0; b < vblocks; ++b)
    edge_first[b + 1] += edge_first[b];
  const int64_t ne = edge_first[vblocks];
  t.cell_edges_.resize(nc);
  t.edge_vertices_.resize(static_cast<std::size_t>(ne));
  t.edge_cells_.resize(rec.size());
  t.edge_cell_offset_.resize(static_cast<std::size_t>(ne) + 1);
  t.edge_cell_offset_[ne] = static_cast<int64_t>(rec.size());
  // The local edge of each (edge, cell) incidence, in edge_cells_ order: the orientation walk
  // below finds a neighbour's side of the shared edge there, not by searching the neighbour.
  UninitializedVector<int8_t> incidence_local(rec.size()); // every slot written below
  {
    BlockProblems found(vblocks);
    std::vector<int64_t> boundary(static_cast<std::size_t>(vblocks), 0);
    parallel_chunks(nv, vblocks, vertex_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
      int64_t e = edge_first[b], boundary_here = 0;
      for (int64_t lo = begin; lo < end; ++lo)
        for (int64_t i = bucket[lo]; i < bucket[lo + 1]; ++e) {
          int64_t j = i;
          while (j < bucket[lo + 1] && rec[j].hi == rec[i].hi)
            ++j;
          const int64_t hi = rec[i].hi;
          t.edge_vertices_[e] = {lo, hi};
          t.edge_cell_offset_[e] = i;
          for (int64_t r = i; r < j; ++r) {
            const int64_t cell = rec[r].cell_local / 3;
            const int local = static_cast<int>(rec[r].cell_local % 3);
            t.cell_edges_[cell][local] = e;
            incidence_local[r] = static_cast<int8_t>(local);
            t.edge_cells_[r] = cell;
          }
          const int64_t count = j - i;
          if (count == 1)
            ++boundary_here;
          if (count > 2) {
            std::ostringstream m;
            m << "edge between points " << t.vertex_point_[lo] << " and " << t.vertex_point_[hi]
              << " is shared by " << count << " cells (";
            for (int64_t r = i; r < j; ++r)
              m << (r > i ? ", " : "") << rec[r].cell_local / 3;
            m << ")";
            found[b].add(Problem::NonManifoldEdge, m.str());
          }
          if (count == 2 && rec[i].cell_local / 3 == rec[i + 1].cell_local / 3) {
            found[b].add(Problem::RepeatedEdge, "cell " + std::to_string(rec[i].cell_local / 3) +
                                                    " uses the same edge twice");
          }
          i = j;
        }
      boundary[b] = boundary_here; // once per block: the blocks' slots share cache lines
    });
    found.append_to(problems);
    for (int64_t n : boundary)
      t.boundary_edges_ += n;
  }
  UninitializedVector<EdgeRecord>().swap(rec);
  t.cell_edge_reversed_.resize(nc);
  parallel_for(nc, cell_threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t c = begin; c < end; ++c) {
      uint8_t reversed = 0;
      for (int k = 0; k < 3; ++k)
        if (t.cell_vertices_[c][k] != t.edge_vertices_[t.cell_edges_[c][k]][0])
          reversed |= static_cast<uint8_t>(1u << k);
      t.cell_edge_reversed_[c] = reversed;
    }
  });

  // Components and a consistent orientation. Most inputs are consistently oriented already (the
  // two cells of every manifold edge run it in opposite directions): then every cell keeps
  // parity +1, as the walk below would give it, and only the components remain to count, by
  // disjoint sets over the edges in edge order (no walk from cell to cell through memory).
  const int edge_threads = threads_for(ne, threads, 32768);
  std::atomic<bool> consistent{true};
  parallel_for(ne, edge_threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t e = begin; e < end && consistent.load(std::memory_order_relaxed); ++e) {
      const int64_t at = t.edge_cell_offset_[e];
      if (t.edge_cell_offset_[e + 1] - at != 2)
        continue;
      const int64_t c0 = t.edge_cells_[at], c1 = t.edge_cells_[at + 1];
      if (c0 != c1 &&
          t.edge_reversed(c0, incidence_local[at]) == t.edge_reversed(c1, incidence_local[at + 1]))
        consistent.store(false, std::memory_order_relaxed);
    }
  });
  if (consistent) {
    t.cell_parity_.resize(nc);
    std::fill(t.cell_parity_.begin(), t.cell_parity_.end(), int8_t{1});
    ConcurrentSets cells(nc, threads);
    parallel_for(ne, edge_threads, [&](int64_t begin, int64_t end, int) {
      for (int64_t e = begin; e < end; ++e) {
        const int64_t at = t.edge_cell_offset_[e];
        if (t.edge_cell_offset_[e + 1] - at == 2)
          cells.unite(t.edge_cells_[at], t.edge_cells_[at + 1]);
      }
    });
    t.components_ = cells.count(threads);
  }
  // Otherwise a breadth-first walk over manifold edges gives each cell its parity.
  if (!consistent) {
    t.cell_parity_.resize(nc);
    std::fill(t.cell_parity_.begin(), t.cell_parity_.end(), int8_t{0});
  }
  std::vector<int64_t> queue;
  int64_t orientation_conflicts = 0;
  for (int64_t s = 0; s < nc && !consistent; ++s) {
    if (t.cell_parity_[s] != 0)
      continue;
    ++t.components_;
    t.cell_parity_[s] = 1;
    queue.assign(1, s);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int64_t c = queue[q];
      for (int k = 0; k < 3; ++k) {
        const int64_t e = t.cell_edges_[c][k];
        if (t.edge_cell_count(e) != 2)
          continue;
        const int64_t at = t.edge_cell_offset_[e] + (t.edge_cells_[t.edge_cell_offset_[e]] == c);
        const int64_t n = t.edge_cells_[at];
        if (n == c)
          continue;
        const int kn = incidence_local[at];
        // Consistently oriented neighbours run the shared edge in opposite directions.
        const bool same_dir = t.edge_reversed(c, k) == t.edge_reversed(n, kn);
        const int8_t want = static_cast<int8_t>(same_dir ? -t.cell_parity_[c] : t.cell_parity_[c]);
        if (t.cell_parity_[n] == 0) {
          t.cell_parity_[n] = want;
          queue.push_back(n);
        } else if (t.cell_parity_[n] != want) {
          ++orientation_conflicts;
        }
      }
    }
  }
  if (orientation_conflicts > 0) {
    t.orientable_ = false;
    problems.add(Problem::NonOrientable, "the cells cannot be oriented consistently (" +
                                             std::to_string(orientation_conflicts / 2) +
                                             " conflicting edges)");
  }

  // Fans at open points are not checked (the input holds only part of them).
  auto is_open = [&](int64_t v) {
    const int64_t p = t.vertex_point_[v];
    return p < static_cast<int64_t>(open_points.size()) && open_points[p] != 0;
  };

  // Boundary loops: components of the boundary-edge graph; every boundary vertex of a manifold
  // has exactly two boundary edges.
  const int vertex_loop_threads = threads_for(nv, threads, 32768);
  PooledVector<int64_t> boundary_degree(static_cast<std::size_t>(nv), 0);
  {
    ConcurrentSets loops(nv, threads);
    parallel_for(ne, edge_threads, [&](int64_t begin, int64_t end, int) {
      for (int64_t e = begin; e < end; ++e)
        if (t.is_boundary_edge(e)) {
          add_one(boundary_degree[t.edge_vertices_[e][0]]);
          add_one(boundary_degree[t.edge_vertices_[e][1]]);
          loops.unite(t.edge_vertices_[e][0], t.edge_vertices_[e][1]);
        }
    });
    BlockProblems pinched(vblocks);
    std::vector<int64_t> roots(static_cast<std::size_t>(vblocks), 0);
    parallel_chunks(nv, vblocks, vertex_loop_threads,
                    [&](int64_t b, int64_t begin, int64_t end, int) {
                      int64_t roots_here = 0;
                      for (int64_t v = begin; v < end; ++v) {
                        if (boundary_degree[v] == 0)
                          continue;
                        roots_here += loops.find(v) == v;
                        if (boundary_degree[v] != 2 && !is_open(v))
                          pinched[b].add(Problem::NonManifoldVertex,
                                         "point " + std::to_string(t.vertex_point_[v]) +
                                             " touches " + std::to_string(boundary_degree[v]) +
                                             " boundary edges (a pinch: two boundary loops meet "
                                             "there)");
                      }
                      roots[b] = roots_here;
                    });
    pinched.append_to(problems);
    for (int64_t r : roots)
      t.boundary_loops_ += r;
  }

  // Vertices whose cells form more than one fan: two parts of the surface touching at a single
  // vertex. Counting cannot see it (two cycles of cells around a vertex have as many manifold
  // edges there as one), so each vertex's fan is walked, from its lowest cell, across manifold
  // edges from cell to cell until it closes or meets the boundary on both sides. Every corner
  // belongs to one vertex, so the fans cover every corner exactly when each vertex has one fan:
  // the walks' lengths are summed first, and only when they fall short is each vertex looked
  // at. Edges with more than two cells and cells with a repeated corner (reported above) make
  // fans ill-defined: the walk is skipped then.
  const bool walkable = problems.count(Problem::NonManifoldEdge) == 0 &&
                        problems.count(Problem::RepeatedCorner) == 0 &&
                        problems.count(Problem::RepeatedEdge) == 0;
  // The cells in v's fan through corner k of cell c.
  auto fan_size = [&](int64_t v, int64_t c0, int k0) {
    int64_t size = 1;
    // Out of cell c through its edge j at v, around v, until the fan closes (true) or an edge
    // has one cell.
    auto walk = [&](int64_t c, int j) {
      for (int64_t steps = 0; steps < 3 * nc; ++steps) {
        const int64_t e = t.cell_edges_[c][j];
        const int64_t at = t.edge_cell_offset_[e];
        if (t.edge_cell_offset_[e + 1] - at != 2)
          return false;
        const int64_t side = t.edge_cells_[at] == c ? at + 1 : at;
        const int64_t n = t.edge_cells_[side];
        const int jn = incidence_local[side];
        const int kn = t.cell_vertices_[n][jn] == v ? jn : (jn + 1) % 3;
        if (n == c0 && kn == k0)
          return true;
        ++size;
        // Leave n through its other edge at v: edge kn starts at corner kn, edge kn + 2 ends
        // there.
        c = n;
        j = jn == kn ? (kn + 2) % 3 : kn;
      }
      return true; // not reached: a fan has fewer cells than the mesh
    };
    if (!walk(c0, k0))
      walk(c0, (k0 + 2) % 3);
    return size;
  };
  // An open vertex counts its corners as if they formed one fan.
  std::vector<int64_t> open_corner_count;
  if (walkable && !open_points.empty()) {
    open_corner_count.assign(static_cast<std::size_t>(nv), 0);
    parallel_for(nc, cell_threads, [&](int64_t begin, int64_t end, int) {
      for (int64_t c = begin; c < end; ++c)
        for (int k = 0; k < 3; ++k)
          if (is_open(t.cell_vertices_[c][k]))
            add_one(open_corner_count[t.cell_vertices_[c][k]]);
    });
  }
  auto open_corners = [&](int64_t v) { return open_corner_count[v]; };
  int64_t fan_cells = 0;
  if (walkable) {
    std::vector<int64_t> block_cells(static_cast<std::size_t>(vblocks), 0);
    parallel_chunks(nv, vblocks, vertex_loop_threads,
                    [&](int64_t b, int64_t begin, int64_t end, int) {
                      int64_t cells = 0;
                      for (int64_t v = begin; v < end; ++v)
                        cells += is_open(v) ? open_corners(v)
                                            : fan_size(v, t.vertex_cell_[v], t.vertex_corner_[v]);
                      block_cells[b] = cells;
                    });
    for (int64_t n : block_cells)
      fan_cells += n;
  }
  if (walkable && fan_cells != 3 * nc) {
    // Some vertex has more than one fan: which ones (rare, so serially).
    std::vector<int64_t> corners(static_cast<std::size_t>(nv), 0);
    for (int64_t c = 0; c < nc; ++c)
      for (int k = 0; k < 3; ++k)
        ++corners[t.cell_vertices_[c][k]];
    for (int64_t v = 0; v < nv; ++v) {
      const int64_t fan = fan_size(v, t.vertex_cell_[v], t.vertex_corner_[v]);
      // More than two boundary edges: reported above as a pinch of boundary loops.
      if (fan != corners[v] && boundary_degree[v] <= 2 && !is_open(v))
        problems.add(Problem::NonManifoldVertex,
                     "point " + std::to_string(t.vertex_point_[v]) + ": its " +
                         std::to_string(corners[v]) + " cells form more than one fan (" +
                         std::to_string(fan) + " of them around cell " +
                         std::to_string(t.vertex_cell_[v]) +
                         "): two parts of the surface touch at this single vertex");
    }
  }
  return t;
}

} // namespace hoct
