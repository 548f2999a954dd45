#include "mesh/piece_surface.hpp"

#include "util/byte_codec.hpp"
#include "util/concurrent_sets.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace hoct {

PieceSurface summarize_piece(const Topology &t, std::span<const int64_t> global_point,
                             std::span<const std::array<int32_t, 2>> spans, int32_t piece,
                             int threads) {
  PieceSurface s;
  s.piece = s.last_piece = piece;
  s.vertices = t.num_vertices();
  s.edges = t.num_edges();
  s.triangles = t.num_cells();
  s.components = t.components();
  s.orientable = t.orientable();
  const int64_t nv = t.num_vertices(), ne = t.num_edges(), nc = t.num_cells();
  auto open = [&](int64_t v) {
    const std::size_t p = static_cast<std::size_t>(t.vertex_point(v));
    return p < spans.size() && spans[p][0] != spans[p][1];
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
  for (int64_t v = 0; v < nv; ++v)
    if (open(v)) {
      const auto &span = spans[static_cast<std::size_t>(t.vertex_point(v))];
      s.open.push_back(OpenPoint{global(v), span[0], span[1]});
    }
  std::sort(s.open.begin(), s.open.end(),
            [](const OpenPoint &x, const OpenPoint &y) { return x.point < y.point; });
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

PieceSurface empty_piece_surface(int32_t piece) {
  PieceSurface s;
  s.piece = s.last_piece = piece;
  return s;
}

PieceSurface merge_piece_surfaces(const PieceSurface &a, const PieceSurface &b) {
  PieceSurface out;
  out.piece = std::min(a.piece, b.piece);
  out.last_piece = std::max(a.last_piece, b.last_piece);
  out.vertices = a.vertices + b.vertices;
  out.edges = a.edges + b.edges;
  out.triangles = a.triangles + b.triangles;
  out.components = a.components + b.components;
  out.closed_loops = a.closed_loops + b.closed_loops;
  out.orientable = a.orientable && b.orientable;
  out.problem = a.problem.empty() ? b.problem : a.problem;
  auto note = [&](std::string what) {
    if (out.problem.empty())
      out.problem = std::move(what);
  };

  // The open points of both, each once: a point both count is one vertex.
  std::vector<OpenPoint> open;
  open.reserve(a.open.size() + b.open.size());
  for (std::size_t i = 0, j = 0; i < a.open.size() || j < b.open.size();) {
    if (j == b.open.size() || (i < a.open.size() && a.open[i].point < b.open[j].point)) {
      open.push_back(a.open[i++]);
    } else if (i == a.open.size() || b.open[j].point < a.open[i].point) {
      open.push_back(b.open[j++]);
    } else {
      open.push_back(OpenPoint{a.open[i].point, std::min(a.open[i].first, b.open[j].first),
                               std::max(a.open[i].last, b.open[j].last)});
      --out.vertices;
      ++i;
      ++j;
    }
  }
  // Settled: every piece using it is in [out.piece, out.last_piece].
  auto settled = [&](int64_t point) {
    const auto it = std::lower_bound(open.begin(), open.end(), point,
                                     [](const OpenPoint &o, int64_t p) { return o.point < p; });
    return it != open.end() && it->point == point && it->first >= out.piece &&
           it->last <= out.last_piece;
  };
  const std::array<const PieceSurface *, 2> sides = {&a, &b};

  // The fans at settled points: each one's triangles, from both sides, one path or cycle.
  struct Corner {
    int64_t point, next, prev;
    bool operator<(const Corner &o) const { return point < o.point; }
  };
  std::vector<Corner> corners;
  for (const PieceSurface *side : sides)
    for (const BandTriangle &t : side->band)
      for (int k = 0; k < 3; ++k)
        if ((t.open >> k & 1) && settled(t.point[k]))
          corners.push_back({t.point[k], t.point[(k + 1) % 3], t.point[(k + 2) % 3]});
  std::sort(corners.begin(), corners.end());
  std::vector<int64_t> ids;
  std::vector<std::size_t> parent;
  std::vector<int> degree;
  for (std::size_t i = 0; i < corners.size();) {
    std::size_t j = i;
    while (j < corners.size() && corners[j].point == corners[i].point)
      ++j;
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
      const std::size_t x = std::lower_bound(ids.begin(), ids.end(), corners[k].next) - ids.begin();
      const std::size_t y = std::lower_bound(ids.begin(), ids.end(), corners[k].prev) - ids.begin();
      ++degree[x];
      ++degree[y];
      const std::size_t rx = root(x), ry = root(y);
      if (rx != ry) {
        parent[ry] = rx;
        --groups;
      }
    }
    const auto most = std::max_element(degree.begin(), degree.end());
    if (most != degree.end() && *most > 2)
      note("the edge between points " + std::to_string(corners[i].point) + " and " +
           std::to_string(ids[most - degree.begin()]) + " is shared by " + std::to_string(*most) +
           " cells");
    else if (groups > 1)
      note("the cells at point " + std::to_string(corners[i].point) + " form " +
           std::to_string(groups) + " fans: parts of the surface touch at this single vertex");
    i = j;
  }

  // Edges between open points: shared by the two sides, inside one, or (one triangle, an end
  // settled) on the whole's boundary; with both ends still open and one triangle, undecided.
  KeyIndex component_index, run_index;
  for (const PieceSurface *side : sides)
    for (const BandTriangle &t : side->band)
      component_index.get(t.piece, t.component);
  struct SeamEdge {
    int64_t lo, hi;
    std::size_t component;
    int side;
    int8_t turn; // +1 if the triangle runs lo -> hi in its orientation (parity applied)
    bool operator<(const SeamEdge &o) const {
      return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : side < o.side;
    }
  };
  std::vector<SeamEdge> seam;
  for (int side = 0; side < 2; ++side)
    for (const BandTriangle &t : sides[side]->band)
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        if (!(t.open >> k & 1) || !(t.open >> k1 & 1))
          continue;
        const int64_t x = t.point[k], y = t.point[k1];
        const int8_t forward = x < y ? 1 : -1;
        seam.push_back({std::min(x, y), std::max(x, y), component_index.get(t.piece, t.component),
                        side, static_cast<int8_t>(forward * t.parity)});
      }
  std::sort(seam.begin(), seam.end());
  ParitySets sets(component_index.at.size());
  std::vector<std::array<std::size_t, 2>> links; // boundary runs: run - point, point - point
  for (std::size_t i = 0; i < seam.size();) {
    std::size_t j = i;
    while (j < seam.size() && seam[j].lo == seam[i].lo && seam[j].hi == seam[i].hi)
      ++j;
    if (j - i == 1) {
      if (settled(seam[i].lo) || settled(seam[i].hi))
        links.push_back({run_index.get(seam[i].lo, 0), run_index.get(seam[i].hi, 0)});
    } else if (j - i == 2 && seam[i].side != seam[i + 1].side) {
      --out.edges; // counted by both sides
      // Consistent orientations run a shared edge in opposite directions: the components'
      // flips differ exactly when the two triangles run it the same way.
      const int r = sets.unite(seam[i].component, seam[i + 1].component,
                               seam[i].turn == seam[i + 1].turn ? 1 : 0);
      if (r == 1)
        --out.components;
      else if (r == -1)
        out.orientable = false;
    } else if (j - i > 2) {
      note("the edge between points " + std::to_string(seam[i].lo) + " and " +
           std::to_string(seam[i].hi) + " is shared by " + std::to_string(j - i) + " cells");
    }
    i = j;
  }

  // Boundary loops: the sides' runs joined at open points and by the boundary edges found here.
  // A group of them with no point still open is a loop; the others are the merged summary's runs.
  for (const PieceSurface *side : sides)
    for (const LoopEnd &e : side->loop_ends)
      links.push_back({run_index.get(-1 - int64_t{e.piece}, e.run), run_index.get(e.point, 0)});
  ParitySets loops(run_index.at.size());
  for (const auto &[x, y] : links)
    loops.unite(x, y, 0);
  std::vector<int64_t> run_of(run_index.at.size(), -1); // per root: the merged run, or -1
  std::vector<uint8_t> root_open(run_index.at.size(), 0);
  for (const auto &[key, index] : run_index.at)
    if (key.first >= 0 && !settled(key.first))
      root_open[loops.find(index).first] = 1;
  std::vector<std::pair<int64_t, std::size_t>> open_nodes; // (point, root), by point
  for (const auto &[key, index] : run_index.at) {
    const std::size_t root = loops.find(index).first;
    if (key.first >= 0 && !settled(key.first))
      open_nodes.emplace_back(key.first, root);
    else if (root == index && !root_open[root])
      ++out.closed_loops;
  }
  std::sort(open_nodes.begin(), open_nodes.end());
  int64_t runs = 0;
  for (const auto &[point, root] : open_nodes) {
    if (run_of[root] < 0)
      run_of[root] = runs++;
    out.loop_ends.push_back(LoopEnd{point, run_of[root], out.piece, 0});
  }

  // The band: the triangles at points still open, their components the merged ones (relabelled
  // densely, in order of first use, and oriented as their merged component's root).
  std::vector<int64_t> label(component_index.at.size(), -1);
  int64_t labels = 0;
  for (const PieceSurface *side : sides)
    for (const BandTriangle &t : side->band) {
      uint8_t mask = 0;
      for (int k = 0; k < 3; ++k)
        if ((t.open >> k & 1) && !settled(t.point[k]))
          mask = static_cast<uint8_t>(mask | 1 << k);
      if (mask == 0)
        continue;
      const auto [root, flip] = sets.find(component_index.get(t.piece, t.component));
      if (label[root] < 0)
        label[root] = labels++;
      BandTriangle u = t;
      u.component = label[root];
      u.piece = out.piece;
      u.parity = static_cast<int8_t>(flip ? -t.parity : t.parity);
      u.open = mask;
      out.band.push_back(u);
    }
  for (const OpenPoint &o : open)
    if (!(o.first >= out.piece && o.last <= out.last_piece))
      out.open.push_back(o);
  return out;
}

SurfaceShape surface_shape(const PieceSurface &all) {
  if (!all.open.empty())
    throw std::logic_error("surface_shape: " + std::to_string(all.open.size()) +
                           " points are used by pieces the summary does not hold");
  SurfaceShape out;
  out.components = all.components;
  out.orientable = all.orientable;
  out.boundary_loops = all.closed_loops;
  out.euler_characteristic = all.vertices - all.edges + all.triangles;
  out.seam_problem = all.problem;
  return out;
}

SurfaceShape glue_pieces(std::vector<PieceSurface> pieces) {
  if (pieces.empty())
    return SurfaceShape{};
  std::sort(pieces.begin(), pieces.end(),
            [](const PieceSurface &x, const PieceSurface &y) { return x.piece < y.piece; });
  for (std::size_t step = 1; step < pieces.size(); step *= 2)
    for (std::size_t i = 0; i + step < pieces.size(); i += 2 * step)
      pieces[i] = merge_piece_surfaces(pieces[i], pieces[i + step]);
  return surface_shape(pieces.front());
}

std::vector<std::byte> encode_piece_surface(const PieceSurface &s) {
  ByteWriter w;
  w.value(s.piece);
  w.value(s.last_piece);
  w.value(s.vertices);
  w.value(s.edges);
  w.value(s.triangles);
  w.value(s.components);
  w.value(s.closed_loops);
  w.value(static_cast<uint8_t>(s.orientable));
  w.array(s.band);
  w.array(s.loop_ends);
  w.array(s.open);
  w.text(s.problem);
  return std::move(w.out);
}

PieceSurface decode_piece_surface(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "decode_piece_surface");
  PieceSurface s;
  s.piece = r.value<int32_t>();
  s.last_piece = r.value<int32_t>();
  s.vertices = r.value<int64_t>();
  s.edges = r.value<int64_t>();
  s.triangles = r.value<int64_t>();
  s.components = r.value<int64_t>();
  s.closed_loops = r.value<int64_t>();
  s.orientable = r.value<uint8_t>() != 0;
  s.band = r.array<BandTriangle>();
  s.loop_ends = r.array<LoopEnd>();
  s.open = r.array<OpenPoint>();
  s.problem = r.text();
  if (!r.done())
    throw std::runtime_error("decode_piece_surface: bytes left after the summary");
  return s;
}

} // namespace hoct
