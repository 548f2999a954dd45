#include "mesh/piece_surface.hpp"

#include "util/byte_codec.hpp"
#include "util/concurrent_sets.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace hoct {

PieceSurface summarize_piece(const Topology &t, std::span<const int64_t> global_point,
                             std::span<const uint8_t> open_points, int32_t piece, int threads) {
  PieceSurface s;
  s.piece = piece;
  s.vertices = t.num_vertices();
  s.edges = t.num_edges();
  s.triangles = t.num_cells();
  s.components = t.components();
  s.orientable = t.orientable();
  const int64_t nv = t.num_vertices(), ne = t.num_edges(), nc = t.num_cells();
  auto open = [&](int64_t v) {
    const int64_t p = t.vertex_point(v);
    return p < static_cast<int64_t>(open_points.size()) && open_points[p] != 0;
  };
  auto global = [&](int64_t v) { return global_point[t.vertex_point(v)]; };

  // Components of the piece's triangles (across edges of two triangles, as Topology counts
  // them): labels for the band.
  ConcurrentSets cells(nc, threads);
  parallel_for(ne, threads_for(ne, threads, 32768), [&](int64_t begin, int64_t end, int) {
    for (int64_t e = begin; e < end; ++e)
      if (t.edge_cell_count(e) == 2)
        cells.unite(t.edge_cells_begin(e)[0], t.edge_cells_begin(e)[1]);
  });
  for (int64_t c = 0; c < nc; ++c) {
    const auto &v = t.cell_vertices(c);
    const uint8_t mask =
        static_cast<uint8_t>((open(v[0]) ? 1 : 0) | (open(v[1]) ? 2 : 0) | (open(v[2]) ? 4 : 0));
    if (mask == 0)
      continue;
    BandTriangle b;
    b.point = {global(v[0]), global(v[1]), global(v[2])};
    b.component = cells.find(c);
    b.piece = piece;
    b.parity = t.cell_parity(c);
    b.open = mask;
    s.band.push_back(b);
  }

  // Boundary runs: the piece's boundary edges with a point no other piece uses are boundary
  // edges of the whole; their components are closed loops (no open point) or runs that end at
  // open points, where the glue continues them.
  ConcurrentSets runs(nv, 1);
  std::vector<uint8_t> touched(static_cast<std::size_t>(nv), 0);
  for (int64_t e = 0; e < ne; ++e) {
    if (!t.is_boundary_edge(e))
      continue;
    const auto &ev = t.edge_vertices(e);
    if (open(ev[0]) && open(ev[1]))
      continue; // the glue decides: another piece may hold it
    runs.unite(ev[0], ev[1]);
    touched[ev[0]] = touched[ev[1]] = 1;
  }
  std::vector<uint8_t> run_open(static_cast<std::size_t>(nv), 0);
  for (int64_t v = 0; v < nv; ++v)
    if (touched[v] && open(v)) {
      const int64_t r = runs.find(v);
      run_open[r] = 1;
      s.loop_ends.push_back(LoopEnd{global(v), r, piece, 0});
    }
  for (int64_t v = 0; v < nv; ++v)
    if (touched[v] && runs.find(v) == v && !run_open[v])
      ++s.closed_loops;
  return s;
}

namespace {

// Disjoint sets with the parity of each element relative to its root.
class ParitySets {
public:
  explicit ParitySets(std::size_t n) : parent_(n), parity_(n, 0) {
    for (std::size_t i = 0; i < n; ++i)
      parent_[i] = i;
  }
  std::pair<std::size_t, uint8_t> find(std::size_t x) {
    uint8_t p = 0;
    std::size_t r = x;
    while (parent_[r] != r) {
      p ^= parity_[r];
      r = parent_[r];
    }
    // Compress: point x's path at the root with its parity.
    uint8_t q = p;
    while (parent_[x] != x) {
      const std::size_t next = parent_[x];
      const uint8_t own = parity_[x];
      parent_[x] = r;
      parity_[x] = q;
      q ^= own;
      x = next;
    }
    return {r, p};
  }
  // Asks a and b to differ by `rel`; returns 1 if they were joined, 0 if already together, -1 if
  // they were together with the other parity (a conflict).
  int unite(std::size_t a, std::size_t b, uint8_t rel) {
    const auto [ra, pa] = find(a);
    const auto [rb, pb] = find(b);
    if (ra == rb)
      return (pa ^ pb) == rel ? 0 : -1;
    parent_[rb] = ra;
    parity_[rb] = static_cast<uint8_t>(pa ^ pb ^ rel);
    return 1;
  }

private:
  std::vector<std::size_t> parent_;
  std::vector<uint8_t> parity_;
};

// Dense indices for keys (piece, label) or points.
struct KeyIndex {
  struct Hash {
    std::size_t operator()(const std::pair<int64_t, int64_t> &k) const {
      return std::hash<uint64_t>()(static_cast<uint64_t>(k.first) * 0x9e3779b97f4a7c15ull ^
                                   static_cast<uint64_t>(k.second));
    }
  };
  std::unordered_map<std::pair<int64_t, int64_t>, std::size_t, Hash> at;
  std::size_t get(int64_t a, int64_t b) {
    return at.emplace(std::pair{a, b}, at.size()).first->second;
  }
};

} // namespace

SurfaceShape glue_pieces(const std::vector<PieceSurface> &pieces) {
  SurfaceShape out;
  int64_t vertices = 0, edges = 0, triangles = 0, components = 0, closed = 0;
  for (const PieceSurface &p : pieces) {
    vertices += p.vertices;
    edges += p.edges;
    triangles += p.triangles;
    components += p.components;
    closed += p.closed_loops;
    out.orientable = out.orientable && p.orientable;
  }

  // The corners at open points, by point: each open point's fan from every piece.
  struct Corner {
    int64_t point, next, prev;
    int32_t piece;
    bool operator<(const Corner &o) const {
      return point != o.point ? point < o.point : piece < o.piece;
    }
  };
  std::vector<Corner> corners;
  for (const PieceSurface &p : pieces)
    for (const BandTriangle &b : p.band)
      for (int k = 0; k < 3; ++k)
        if (b.open >> k & 1)
          corners.push_back({b.point[k], b.point[(k + 1) % 3], b.point[(k + 2) % 3], b.piece});
  std::sort(corners.begin(), corners.end());
  int64_t extra_copies = 0; // an open point counted by k pieces is k - 1 too many
  std::vector<int64_t> ids;
  std::vector<std::size_t> parent;
  std::vector<int> degree;
  for (std::size_t i = 0; i < corners.size();) {
    std::size_t j = i;
    while (j < corners.size() && corners[j].point == corners[i].point)
      ++j;
    for (std::size_t k = i + 1; k < j; ++k)
      extra_copies += corners[k].piece != corners[k - 1].piece;
    // Its link: an edge (next, prev) per triangle; one fan is a path or a cycle.
    ids.clear();
    for (std::size_t k = i; k < j; ++k) {
      ids.push_back(corners[k].next);
      ids.push_back(corners[k].prev);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    parent.resize(ids.size());
    degree.assign(ids.size(), 0);
    for (std::size_t k = 0; k < ids.size(); ++k)
      parent[k] = k;
    auto root = [&](std::size_t x) {
      while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
      return x;
    };
    std::size_t groups = ids.size();
    for (std::size_t k = i; k < j; ++k) {
      const std::size_t a = std::lower_bound(ids.begin(), ids.end(), corners[k].next) - ids.begin();
      const std::size_t b = std::lower_bound(ids.begin(), ids.end(), corners[k].prev) - ids.begin();
      ++degree[a];
      ++degree[b];
      const std::size_t ra = root(a), rb = root(b);
      if (ra != rb) {
        parent[rb] = ra;
        --groups;
      }
    }
    if (out.seam_problem.empty()) {
      const auto most = std::max_element(degree.begin(), degree.end());
      if (most != degree.end() && *most > 2)
        out.seam_problem = "the edge between points " + std::to_string(corners[i].point) + " and " +
                           std::to_string(ids[most - degree.begin()]) + " is shared by " +
                           std::to_string(*most) + " cells";
      else if (groups > 1)
        out.seam_problem = "the cells at point " + std::to_string(corners[i].point) + " form " +
                           std::to_string(groups) +
                           " fans: parts of the surface touch at this single vertex";
    }
    i = j;
  }

  // Edges between open points: shared by two pieces, a boundary edge of the whole, or inside
  // one piece.
  struct SeamEdge {
    int64_t lo, hi;
    int64_t component;
    int32_t piece;
    int8_t turn; // +1 if the triangle runs lo -> hi in its orientation (parity applied)
    bool operator<(const SeamEdge &o) const {
      return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : piece < o.piece;
    }
  };
  std::vector<SeamEdge> seam;
  for (const PieceSurface &p : pieces)
    for (const BandTriangle &b : p.band)
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        if (!(b.open >> k & 1) || !(b.open >> k1 & 1))
          continue;
        const int64_t x = b.point[k], y = b.point[k1];
        const int8_t forward = x < y ? 1 : -1;
        seam.push_back({std::min(x, y), std::max(x, y), b.component, b.piece,
                        static_cast<int8_t>(forward * b.parity)});
      }
  std::sort(seam.begin(), seam.end());
  KeyIndex component_index, run_index;
  std::vector<std::array<std::size_t, 3>> unions; // component a, component b, relation
  std::vector<std::array<int64_t, 2>> loop_edges; // boundary edges between open points
  int64_t shared_edges = 0;
  for (std::size_t i = 0; i < seam.size();) {
    std::size_t j = i;
    while (j < seam.size() && seam[j].lo == seam[i].lo && seam[j].hi == seam[i].hi)
      ++j;
    if (j - i == 1) {
      loop_edges.push_back({seam[i].lo, seam[i].hi});
    } else if (j - i == 2 && seam[i].piece != seam[i + 1].piece) {
      ++shared_edges;
      // Consistent orientations run a shared edge in opposite directions: the components'
      // flips differ exactly when the two triangles run it the same way.
      unions.push_back({component_index.get(seam[i].piece, seam[i].component),
                        component_index.get(seam[i + 1].piece, seam[i + 1].component),
                        seam[i].turn == seam[i + 1].turn ? 1u : 0u});
    } else if (j - i > 2 && out.seam_problem.empty()) {
      out.seam_problem = "the edge between points " + std::to_string(seam[i].lo) + " and " +
                         std::to_string(seam[i].hi) + " is shared by " + std::to_string(j - i) +
                         " cells";
    }
    i = j;
  }
  ParitySets sets(component_index.at.size());
  for (const auto &[a, b, rel] : unions) {
    const int r = sets.unite(a, b, static_cast<uint8_t>(rel));
    if (r == 1)
      --components;
    else if (r == -1)
      out.orientable = false;
  }

  // Boundary loops: the pieces' closed ones, and the runs joined at open points and by the
  // boundary edges between open points.
  std::vector<std::array<std::size_t, 2>> links;
  for (const PieceSurface &p : pieces)
    for (const LoopEnd &e : p.loop_ends)
      links.push_back({run_index.get(-1 - int64_t{e.piece}, e.run), run_index.get(e.point, 0)});
  for (const auto &[a, b] : loop_edges)
    links.push_back({run_index.get(a, 0), run_index.get(b, 0)});
  ParitySets loops(run_index.at.size());
  int64_t loop_count = static_cast<int64_t>(run_index.at.size());
  for (const auto &[a, b] : links)
    if (loops.unite(a, b, 0) == 1)
      --loop_count;

  out.components = components;
  out.boundary_loops = closed + loop_count;
  out.euler_characteristic = (vertices - extra_copies) - (edges - shared_edges) + triangles;
  return out;
}

std::vector<std::byte> encode_piece_surface(const PieceSurface &s) {
  ByteWriter w;
  w.value(s.piece);
  w.value(s.vertices);
  w.value(s.edges);
  w.value(s.triangles);
  w.value(s.components);
  w.value(s.closed_loops);
  w.value(static_cast<uint8_t>(s.orientable));
  w.array(s.band);
  w.array(s.loop_ends);
  return std::move(w.out);
}

PieceSurface decode_piece_surface(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "decode_piece_surface");
  PieceSurface s;
  s.piece = r.value<int32_t>();
  s.vertices = r.value<int64_t>();
  s.edges = r.value<int64_t>();
  s.triangles = r.value<int64_t>();
  s.components = r.value<int64_t>();
  s.closed_loops = r.value<int64_t>();
  s.orientable = r.value<uint8_t>() != 0;
  s.band = r.array<BandTriangle>();
  s.loop_ends = r.array<LoopEnd>();
  if (!r.done())
    throw std::runtime_error("decode_piece_surface: bytes left after the summary");
  return s;
}

} // namespace hoct
