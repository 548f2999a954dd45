#include "exact/cell_phase.hpp"

#include "cell/critical_curves.hpp"
#include "cell/critical_edges.hpp"
#include "cell/degenerate_points.hpp"
#include "cell/level_edges.hpp"
#include "cell/sector_connections.hpp"
#include "poly/gradient_zeros.hpp"
#include "poly/reference_triangle.hpp"
#include "poly/root_isolation.hpp"
#include "poly/symmetric_eigen2.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <optional>
#include <span>

namespace hoct {
namespace {

using clock_type = Stopwatch::clock;

// Cells per block of the cell loop: a block's critical points are all found before its
// connections, so that each pass is timed once per block, not per cell (a clock read costs
// about as much as a cell without critical points).
constexpr int64_t kCellBlock = 512;

// Points of a critical curve that paths from the cell's other nodes may end at.
constexpr std::size_t kCurveTargets = 8;

// The critical-curve cover's budget in a cell beside a level edge. Beside a plateau (data clamped
// to a level) such cells wiggle, and a cover there takes thousands of boxes, milliseconds per
// cell on every cell of a plateau's border; they fall back instead, as before their constant
// edge was known to be level. A quadratic ridge meeting a level edge (the conductor's) takes a
// few dozen. (Decided by the cell alone, so that pieces of a partitioned mesh decide alike.)
constexpr int64_t kCurveBoxesBesideLevelEdges = 256;

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
  // The block's degenerate critical points (InteriorCritical::degenerate indexes them), and per
  // cell of the block those classified (regular ones included) and their largest slack.
  std::vector<DegenerateCritical> degenerate;
  int32_t degenerate_count[kCellBlock];
  int32_t corner_count[kCellBlock];
  double degenerate_slack[kCellBlock];
  std::vector<const SectorRays *> rays; // the current cell's, parallel to its interior nodes
  // The block's critical corners' sectors, and per cell of the block the index of each
  // corner's (-1: not critical).
  std::vector<SectorRays> corner_rays;
  std::array<int32_t, 3> corner_index[kCellBlock];
  // The block's critical curves (InteriorCritical::curve indexes them), and per cell of the block
  // how many.
  std::vector<CriticalCurve> curves;
  int32_t curve_count[kCellBlock];
  std::vector<Vec2> boundary_points;  // the current cell's corners and edge nodes
  bool beside_level_edge[kCellBlock]; // the block's cells with a level edge
};

// Which corners of cell c are critical: an edge whose derivative vanishes at the vertex
// (kEdgeRootAtVertex; g: the cell's polynomial).
std::array<bool, 3> critical_corners(const Mesh &mesh, const EdgeNodes &en, int64_t c,
                                     const BernsteinTriangle &g) {
  std::array<bool, 3> critical{false, false, false};
  const EdgeNodeOptions defaults;
  std::vector<Root> roots;
  for (int k = 0; k < 3; ++k) {
    if (en.degeneracy[mesh.topology.cell_edge(c, k)] != kEdgeRootAtVertex)
      continue;
    const BernsteinPoly d = g.edge(k).derivative();
    find_roots(d.coefficients(), roots);
    for (const Root &r : roots) {
      if (r.t <= defaults.vertex_tolerance)
        critical[k] = true;
      if (r.t >= 1 - defaults.vertex_tolerance)
        critical[(k + 1) % 3] = true;
    }
  }
  return critical;
}

// The corner of the reference triangle a zero found near its boundary lies at (within 1e-6), or
// -1.
int corner_of(const GradientZero &p) {
  constexpr double kNear = 1e-6;
  if (p.u <= kNear && p.v <= kNear)
    return 0;
  if (p.u >= 1 - kNear && p.v <= kNear)
    return 1;
  if (p.u <= kNear && p.v >= 1 - kNear)
    return 2;
  return -1;
}

// Per corner of cell c, half the distance (in edge parameters) to the nearest node on its two
// edges: each edge is strictly monotone from the corner up to there.
std::array<double, 3> corner_reach(const Mesh &mesh, const EdgeNodes &en, int64_t c) {
  const Topology &topo = mesh.topology;
  std::array<double, 3> reach{0.5, 0.5, 0.5};
  for (int k = 0; k < 3; ++k) {
    const int64_t e = topo.cell_edge(c, k);
    const bool rev = topo.edge_reversed(c, k);
    const int64_t n = en.count(e);
    for (int64_t i = 0; i < n; ++i) {
      const double t = en.nodes[en.offset[e] + i].t;
      const double s = rev ? 1 - t : t; // from corner k towards corner k + 1
      reach[k] = std::min(reach[k], 0.5 * s);
      reach[(k + 1) % 3] = std::min(reach[(k + 1) % 3], 0.5 * (1 - s));
    }
  }
  return reach;
}

// The certified connections of regular cell c (the block's cell block_offset; its interior
// critical points: `critical`; its critical corners' sectors: scratch.corner_index), a
// cell with nodes besides its corners (with only those, every sector lies along an edge),
// appended with its interior nodes to `out`; or, when a sector cannot be connected, the reason
// for falling back (nothing appended).
uint8_t connect_cell(const Mesh &mesh, const EdgeNodes &en, int64_t c, int32_t block_offset,
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
  for (int k = 0; k < 3; ++k) {
    const int64_t v = topo.cell_vertices(c)[k];
    cn.nodes.push_back({kReferenceCorner[k], field.vertex_value(v), v});
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
  // A critical curve's anchors: more points of the same node, where paths may end. Its edge
  // nodes are the node too (joined below): their sectors are the curve's.
  bool curves = false;
  for (std::size_t i = 0; i < critical.size(); ++i)
    if (critical[i].curve >= 0) {
      curves = true;
      const CriticalCurve &cv = scratch.curves[static_cast<std::size_t>(critical[i].curve)];
      // At most kCurveTargets of them, spread along it: each is a target every path tries.
      const std::size_t stride = (cv.anchors.size() + kCurveTargets - 1) / kCurveTargets;
      for (std::size_t k = 0; k < cv.anchors.size(); k += stride)
        cn.nodes.push_back({cv.anchors[k], cv.value, -1 - static_cast<int64_t>(i)});
      std::erase_if(scratch.edge_nodes, [&](const CellEdgeNode &e) {
        return std::find(cv.boundary_nodes.begin(), cv.boundary_nodes.end(), e.node) !=
               cv.boundary_nodes.end();
      });
    }
  std::array<const SectorRays *, 3> corner_rays{nullptr, nullptr, nullptr};
  if (block_offset >= 0)
    for (int k = 0; k < 3; ++k)
      if (const int32_t at = scratch.corner_index[block_offset][k]; at >= 0)
        corner_rays[k] = &scratch.corner_rays[at];
  scratch.rays.clear();
  for (const InteriorCritical &p : critical)
    if (p.degenerate >= 0 || p.curve >= 0) {
      scratch.rays.assign(critical.size(), nullptr);
      for (std::size_t i = 0; i < critical.size(); ++i)
        if (critical[i].degenerate >= 0)
          scratch.rays[i] = &scratch.degenerate[critical[i].degenerate].rays;
        else if (critical[i].curve >= 0)
          scratch.rays[i] = &scratch.curves[static_cast<std::size_t>(critical[i].curve)].rays;
      break;
    }
  const SectorResult &r = scratch.sectors;
  connect_sectors(g, cn, scratch.interior_idx, scratch.edge_nodes, out.counters, scratch.sectors,
                  arc_geometry, scratch.rays, corner_rays);
  if (r.failed || r.degenerate)
    return fallback_bit(r.failed ? FallbackReason::CertificationFailed
                                 : FallbackReason::DegenerateEdgeNode);
  // The cell's interior node i becomes the chunk's node first + i.
  const int64_t first = static_cast<int64_t>(out.nodes.size());
  for (const InteriorCritical &p : critical)
    out.nodes.push_back({c, p.uv, p.value});
  auto ref = [&](int64_t r) { return r >= 0 ? r : -1 - (first + (-1 - r)); };
  for (auto [a, b] : r.join)
    out.join.push_back({ref(a), ref(b)});
  for (auto [a, b] : r.split)
    out.split.push_back({ref(a), ref(b)});
  // A critical curve's corners and edge nodes: the same node, in both graphs.
  std::vector<std::pair<int64_t, int64_t>> same;
  if (curves)
    for (std::size_t i = 0; i < critical.size(); ++i)
      if (critical[i].curve >= 0)
        for (int b : scratch.curves[static_cast<std::size_t>(critical[i].curve)].boundary_nodes) {
          same.emplace_back(cn.nodes[static_cast<std::size_t>(b)].ref,
                            -1 - static_cast<int64_t>(i));
          out.join.push_back({ref(same.back().first), ref(same.back().second)});
          out.split.push_back({ref(same.back().first), ref(same.back().second)});
        }
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
      for (auto [a, b] : same)
        out.geo.push_back({ref(a), ref(b), {}});
    }
  return 0;
}

// True if an interior critical point's Hessian has an eigenvalue below 1e-3 of the Hessian's
// scale over the cell: a degenerate point, possibly split by the data's rounding into regular
// ones whose sectors no path could connect.
bool nearly_singular_hessian(const BernsteinTriangle &g,
                             std::span<const InteriorCritical> critical) {
  const int d = g.degree();
  if (critical.empty() || d < 2)
    return false;
  double scale = 0;
  for (int b = 0; b <= d - 2; ++b)
    for (int a = 0; a + b <= d - 2; ++a)
      scale = std::max(
          {scale,
           std::abs(g.coefficient(a + 2, b) - 2 * g.coefficient(a + 1, b) + g.coefficient(a, b)),
           std::abs(g.coefficient(a, b + 2) - 2 * g.coefficient(a, b + 1) + g.coefficient(a, b))});
  scale *= d * (d - 1);
  for (const InteriorCritical &p : critical) {
    if (std::abs(symmetric_eigen2(g.jet(p.uv[0], p.uv[1]).hessian).smaller()) <= 1e-3 * scale)
      return true;
  }
  return false;
}

// True if a certified zero's Hessian, in the cell's own shape (frame T: H' = T^-T H T^-1, so
// that a sliver's anisotropy does not count), has eigenvalues a million times apart: a ridge or
// valley that the data's rounding split into regular points.
// (The frame is asked for only where the reference Hessian is that singular to 1e-2 already: it
// is the rare case, and the cell's shape changes the ratio by at most its condition squared.)
bool split_ridge(const BernsteinTriangle &g, const GradientZeros &z,
                 const std::function<Mat2()> &frame) {
  auto ratio = [](const Mat2 &h) {
    const SymmetricEigen2 e = symmetric_eigen2(h);
    const double lo = std::abs(e.smaller()), hi = std::abs(e.larger());
    return hi > 0 ? lo / hi : 1.0;
  };
  std::optional<Mat2> inv;
  for (const GradientZero &p : z.zeros) {
    const Mat2 h = g.jet(p.u, p.v).hessian;
    if (!(ratio(h) <= 1e-2))
      continue;
    if (!inv) {
      const Mat2 t = frame();
      const double det = t[0][0] * t[1][1] - t[0][1] * t[1][0];
      if (!(std::abs(det) > 0))
        return false;
      inv = Mat2{{{t[1][1] / det, -t[0][1] / det}, {-t[1][0] / det, t[0][0] / det}}};
    }
    Mat2 m{}, hp{}; // m = H inv, hp = inv^T m
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        m[i][j] = h[i][0] * (*inv)[0][j] + h[i][1] * (*inv)[1][j];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        hp[i][j] = (*inv)[0][i] * m[0][j] + (*inv)[1][i] * m[1][j];
    if (ratio(hp) <= 1e-6)
      return true;
  }
  return false;
}

} // namespace

CellPhase run_cell_phase(const Mesh &mesh, const EdgeNodes &en, const ExactTreeOptions &opt,
                         int threads) {
  const Topology &topo = mesh.topology;
  const Field &field = mesh.field;
  const int64_t nc = topo.num_cells();
  CellPhase phase;
  UninitializedVector<uint8_t> &fallback = phase.fallback; // every cell's entry is written below
  fallback.resize(static_cast<std::size_t>(nc));
  const int64_t chunks = threads > 1 ? std::min<int64_t>(nc, int64_t{threads} * 16) : 1;
  phase.chunks.resize(static_cast<std::size_t>(chunks));
  std::vector<CellChunk> &chunk_out = phase.chunks;
  parallel_chunks(nc, chunks, threads, [&](int64_t k, int64_t begin, int64_t end, int) {
    CellChunk &out = chunk_out[k];
    // The cell shape, asked for only when a sliver's reference-triangle search leaves zeros
    // unresolved (find_gradient_zeros then retries in that shape).
    int64_t cell = begin;
    GradientZeroOptions zero_options;
    zero_options.frame = [&] { return mesh.geometry.frame(cell); };
    // Beside a level edge (a plateau's border, where cells wiggle and searches are at their
    // costliest) the search gives up sooner: such cells fell back unsearched before their edge
    // was known to be level.
    GradientZeroOptions level_options = zero_options;
    level_options.deep_limit = 4;
    CellScratch scratch;
    auto block_start = clock_type::now();
    for (int64_t block = begin; block < end; block += kCellBlock) {
      const int64_t block_end = std::min(end, block + kCellBlock);
      // Pass 1: the cells' interior critical points, and which cells fall back.
      scratch.critical.clear();
      scratch.degenerate.clear();
      scratch.curves.clear();
      scratch.corner_rays.clear();
      int connect_count = 0;
      // The critical corners `marks` of cell c classified (scratch.poly holds its polynomial):
      // its other zeros and the corners' sectors go to the scratch; false if not certified.
      auto try_corners = [&](int64_t c, const std::array<bool, 3> &marks, bool search) {
        CornerResolution res =
            resolve_critical_corners(scratch.poly, marks, corner_reach(mesh, en, c), zero_options,
                                     search, field.precision());
        if (!res.resolved)
          return false;
        int32_t count = 0;
        for (const GradientZero &p : res.zeros)
          scratch.critical.push_back({{p.u, p.v}, scratch.poly(p.u, p.v)});
        for (int k = 0; k < 3; ++k)
          if (res.corners[k]) {
            scratch.corner_index[c - block][k] = static_cast<int32_t>(scratch.corner_rays.size());
            scratch.corner_rays.push_back(std::move(*res.corners[k]));
            ++count;
          }
        scratch.corner_count[c - block] = count;
        scratch.degenerate_slack[c - block] = res.slack;
        return true;
      };
      // The critical curves of cell c (scratch.poly holds its polynomial): classified, their
      // nodes go to the scratch; false if not certified.
      // With `degenerate_edges`, the nodes of the cell's degenerate edges (multiple or flat
      // roots of the edge's derivative, which the edge rule cannot classify) must lie on a curve.
      auto try_curves = [&](int64_t c, bool degenerate_edges = false) {
        std::vector<Vec2> &pts = scratch.boundary_points;
        pts.assign(std::begin(kReferenceCorner), std::end(kReferenceCorner));
        thread_local std::vector<int> must;
        must.clear();
        std::array<bool, 3> corners{false, false, false};
        if (degenerate_edges)
          corners = critical_corners(mesh, en, c, scratch.poly);
        for (int k = 0; k < 3; ++k) {
          const int64_t e = topo.cell_edge(c, k);
          const bool rev = topo.edge_reversed(c, k);
          const int64_t n = en.count(e);
          for (int64_t i = 0; i < n; ++i) {
            const int64_t gi = rev ? en.offset[e] + n - 1 - i : en.offset[e] + i;
            if (degenerate_edges && (en.degeneracy[e] & ~kEdgeRootAtVertex) != 0)
              must.push_back(static_cast<int>(pts.size()));
            pts.push_back(point_on_edge(k, rev ? 1 - en.nodes[gi].t : en.nodes[gi].t));
          }
        }
        CurveResolution res = resolve_critical_curves(
            scratch.poly, pts, field.precision(), corners, corner_reach(mesh, en, c),
            scratch.beside_level_edge[c - block] ? kCurveBoxesBesideLevelEdges : kCurveCoverBoxes);
        if (!res.resolved)
          return false;
        for (int p : must) {
          bool on = false;
          for (const CriticalCurve &cv : res.curves)
            on = on || std::find(cv.boundary_nodes.begin(), cv.boundary_nodes.end(), p) !=
                           cv.boundary_nodes.end();
          if (!on)
            return false;
        }
        for (CriticalCurve &cv : res.curves) {
          scratch.critical.push_back(
              {cv.uv, cv.value, -1, static_cast<int32_t>(scratch.curves.size())});
          scratch.curves.push_back(std::move(cv));
        }
        scratch.curve_count[c - block] = static_cast<int32_t>(res.curves.size());
        scratch.degenerate_slack[c - block] = res.slack;
        for (int k = 0; k < 3; ++k)
          if (res.corners[k]) {
            scratch.corner_index[c - block][k] = static_cast<int32_t>(scratch.corner_rays.size());
            scratch.corner_rays.push_back(std::move(*res.corners[k]));
            ++scratch.corner_count[c - block];
          }
        return true;
      };
      for (int64_t c = block; c < block_end; ++c) {
        scratch.critical_first[c - block] = static_cast<int32_t>(scratch.critical.size());
        scratch.curve_count[c - block] = 0;
        scratch.degenerate_count[c - block] = 0;
        scratch.corner_count[c - block] = 0;
        scratch.degenerate_slack[c - block] = 0;
        uint8_t why = 0;
        bool edge_nodes_on = false;
        // Every degenerate edge of the cell only has its derivative vanish at a vertex.
        bool at_vertices = true;
        bool constant_edge = false;
        // Most cells: no gradient zero, decided on the stored coefficients (a constant cell's
        // edges are neither level nor critical edges: not looked at).
        const GradientScreen screen = screen_gradient(field.coefficients(c), field.degree(c),
                                                      zero_options.constant_tolerance);
        // The cell's local edges that are critical edges (a ridge or valley along them), and
        // their largest slack.
        unsigned critical_edge_mask = 0;
        double critical_edge_slack = 0;
        int critical_edge_curves = 0, critical_edge_ends = 0;
        scratch.beside_level_edge[c - block] = false;
        bool poly_set = false; // scratch.poly holds cell c's polynomial
        for (int j = 0; j < 3; ++j) {
          const int64_t e = topo.cell_edge(c, j);
          if (en.degeneracy[e] == kEdgeConstant && screen.verdict != GradientScreen::kConstant) {
            // A constant edge across which the field rises or falls into this cell: a piece of
            // a level set, no node and nothing to classify.
            if (!poly_set)
              scratch.poly.assign(field.degree(c), field.coefficients(c));
            poly_set = true;
            if (is_level_edge(scratch.poly, j, field.precision())) {
              ++out.level_edges;
              scratch.beside_level_edge[c - block] = true;
              continue;
            }
            if (const auto ce = critical_edge(scratch.poly, j, field.precision())) {
              critical_edge_mask |= 1u << j;
              critical_edge_slack = std::max(critical_edge_slack, ce->slack);
              critical_edge_curves += ce->curve;
              critical_edge_ends += ce->curve ? 0 : std::popcount(ce->ends);
              continue;
            }
          }
          if (en.degeneracy[e] != kEdgeOk) {
            why |= fallback_bit(FallbackReason::DegenerateEdge);
            at_vertices = at_vertices && en.degeneracy[e] == kEdgeRootAtVertex;
            constant_edge = constant_edge || (en.degeneracy[e] & kEdgeConstant);
          }
          edge_nodes_on |= en.count(e) != 0;
        }
        scratch.corner_index[c - block] = {-1, -1, -1};
        if (critical_edge_mask != 0) {
          // A ridge or valley along an edge, or a constant edge critical at its ends, the cell
          // on one side of it and without other critical points: its corners' sectors reach the
          // other edges, whose chains connect them. The cell's other degenerate edges may only
          // have their derivative vanish at those corners.
          bool certified = !why || at_vertices;
          if (why && at_vertices) {
            const std::array<bool, 3> cc = critical_corners(mesh, en, c, scratch.poly);
            for (int k = 0; k < 3; ++k) {
              const bool on_curve =
                  (critical_edge_mask >> k & 1u) || (critical_edge_mask >> ((k + 2) % 3) & 1u);
              certified = certified && (!cc[k] || on_curve);
            }
          }
          if (certified) {
            fallback[c] = 0;
            scratch.curve_count[c - block] = critical_edge_curves;
            scratch.corner_count[c - block] = critical_edge_ends;
            scratch.degenerate_slack[c - block] = critical_edge_slack;
            if (edge_nodes_on)
              scratch.to_connect[connect_count++] = static_cast<int32_t>(c - block);
            continue;
          }
          why |= fallback_bit(FallbackReason::DegenerateEdge);
        }
        if (screen.verdict == GradientScreen::kConstant) {
          why |= fallback_bit(FallbackReason::ConstantCell);
        } else if (why && at_vertices) {
          // Critical points at the cell's corners: classified by their sectors inside the cell.
          scratch.poly.assign(field.degree(c), field.coefficients(c));
          cell = c;
          if (try_corners(c, critical_corners(mesh, en, c, scratch.poly),
                          screen.verdict != GradientScreen::kNoZero)) {
            why = 0;
            edge_nodes_on = true; // connected, whatever it holds
          } else if (screen.verdict != GradientScreen::kNoZero && try_curves(c, true)) {
            // The critical vertex lies on a curve of critical points.
            why = 0;
            edge_nodes_on = true;
          }
        } else if (why && !constant_edge && screen.verdict != GradientScreen::kNoZero) {
          // An edge with multiple or flat critical points: where it lies on a curve of
          // critical points (a ridge crossing the edge where the curve turns from ridge to
          // valley), the curve classifies it.
          scratch.poly.assign(field.degree(c), field.coefficients(c));
          cell = c;
          if (try_curves(c, true)) {
            fallback[c] = 0;
            scratch.to_connect[connect_count++] = static_cast<int32_t>(c - block);
            continue;
          }
        } else if (screen.verdict != GradientScreen::kNoZero &&
                   !(why & fallback_bit(FallbackReason::DegenerateEdge))) {
          // (A cell with a degenerate edge falls back whatever its interior holds, and the
          // refinement does not use interior critical points: its zeros are not searched. Next
          // to a plateau such cells are nearly flat, where the search is at its costliest.)
          scratch.poly.assign(field.degree(c), field.coefficients(c));
          const BernsteinTriangle &g = scratch.poly;
          cell = c;
          const bool beside_level = scratch.beside_level_edge[c - block];
          const GradientZeros z =
              find_gradient_zeros(g, beside_level ? level_options : zero_options, screen);
          // Zeros the search cannot certify: degenerate critical points, classified by their
          // sectors where that is certified (not beside a level edge: the cost, as above); else
          // the cell falls back.
          if (!z.constant && (z.budget_exhausted || z.unresolved > 0)) {
            DegenerateResolution res;
            if (!beside_level)
              res = resolve_degenerate_zeros(g, z, zero_options, field.precision());
            if (res.resolved) {
              for (const GradientZero &p : res.zeros) {
                if (p.near_boundary)
                  why |= fallback_bit(FallbackReason::ZeroNearBoundary);
                else
                  scratch.critical.push_back({{p.u, p.v}, g(p.u, p.v)});
              }
              for (DegenerateCritical &p : res.points) {
                scratch.critical.push_back(
                    {p.uv, p.value, static_cast<int32_t>(scratch.degenerate.size())});
                scratch.degenerate.push_back(std::move(p));
              }
              scratch.degenerate_count[c - block] =
                  static_cast<int32_t>(res.points.size() + res.regular);
              scratch.degenerate_slack[c - block] = res.slack;
              fallback[c] = why;
              if (!why)
                scratch.to_connect[connect_count++] = static_cast<int32_t>(c - block);
              continue;
            }
            // A curve of critical points (a ridge or valley): one node per curve.
            if (try_curves(c)) {
              fallback[c] = 0;
              scratch.to_connect[connect_count++] = static_cast<int32_t>(c - block);
              continue;
            }
          }
          // Certified zeros whose Hessian is nearly singular: a ridge or valley the data's
          // rounding split into regular points a few ulps apart. As critical curves, within
          // the data's precision, they are one node.
          if (!z.constant && !z.budget_exhausted && z.unresolved == 0 && !z.zeros.empty()) {
            if (split_ridge(g, z, zero_options.frame) && try_curves(c)) {
              fallback[c] = why;
              if (!why)
                scratch.to_connect[connect_count++] = static_cast<int32_t>(c - block);
              continue;
            }
          }
          // A zero at a corner (the vertex is a critical point, its edges monotone to
          // rounding): the corner's sectors inside the cell, classified.
          std::array<bool, 3> at_corner{false, false, false};
          bool only_corners = !z.constant && !z.budget_exhausted && z.unresolved == 0;
          for (const GradientZero &p : z.zeros)
            if (p.near_boundary) {
              const int k = corner_of(p);
              if (k >= 0)
                at_corner[k] = true;
              else
                only_corners = false;
            }
          if (only_corners && (at_corner[0] || at_corner[1] || at_corner[2])) {
            if (try_corners(c, at_corner, true)) {
              fallback[c] = 0;
              scratch.to_connect[connect_count++] = static_cast<int32_t>(c - block);
              continue;
            }
          }
          if (z.constant)
            why |= fallback_bit(FallbackReason::ConstantCell);
          if (z.budget_exhausted)
            why |= fallback_bit(FallbackReason::CriticalCurve);
          for (const GradientZero &p : z.zeros) {
            if (!p.certified) {
              why |= fallback_bit(FallbackReason::UncertifiedZero);
              ++out.unresolved;
            } else if (p.near_boundary) {
              why |= fallback_bit(FallbackReason::ZeroNearBoundary);
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
        uint8_t why =
            connect_cell(mesh, en, block + i, i, critical, opt.arc_geometry, scratch, out);
        if (why == fallback_bit(FallbackReason::CertificationFailed) &&
            nearly_singular_hessian(scratch.poly, critical)) {
          // A sector of an interior critical point no path connects: often a degenerate point
          // the data's rounding split into nearby regular ones, with tiny Hessians. Classified
          // by the sectors around them together, the cell is connected once more.
          cell = block + i;
          std::vector<Vec2> around;
          for (const InteriorCritical &p : critical)
            around.push_back(p.uv);
          const BernsteinTriangle g(field.degree(cell),
                                    std::vector<double>(field.coefficients(cell).begin(),
                                                        field.coefficients(cell).end()));
          DegenerateResolution res =
              resolve_degenerate_zeros(g, around, zero_options, field.precision());
          bool usable = res.resolved;
          for (const GradientZero &p : res.zeros)
            usable = usable && !p.near_boundary;
          if (usable) {
            std::vector<InteriorCritical> again;
            for (const GradientZero &p : res.zeros)
              again.push_back({{p.u, p.v}, g(p.u, p.v)});
            for (DegenerateCritical &p : res.points) {
              again.push_back({p.uv, p.value, static_cast<int32_t>(scratch.degenerate.size())});
              scratch.degenerate.push_back(std::move(p));
            }
            why = connect_cell(mesh, en, cell, i, again, opt.arc_geometry, scratch, out);
            if (!why) {
              scratch.degenerate_count[i] += static_cast<int32_t>(res.points.size() + res.regular);
              scratch.degenerate_slack[i] = std::max(scratch.degenerate_slack[i], res.slack);
            }
          }
        }
        if ((why == fallback_bit(FallbackReason::DegenerateEdgeNode) ||
             why == fallback_bit(FallbackReason::CertificationFailed)) &&
            scratch.curve_count[i] == 0) {
          // An edge node where the gradient vanishes, or a sector no path connects: often a
          // ridge or valley through the cell, which the data's rounding leaves without interior
          // zeros (the stored polynomial's critical line is then a point, or nothing) or with
          // zeros the search certified but nothing connects. Classified as critical curves, the
          // cell is connected once more.
          cell = block + i;
          const std::size_t before = scratch.critical.size();
          if (try_curves(block + i)) {
            const std::span<const InteriorCritical> again(scratch.critical.data() + before,
                                                          scratch.critical.size() - before);
            why = connect_cell(mesh, en, block + i, i, again, opt.arc_geometry, scratch, out);
            if (why)
              scratch.curve_count[i] = 0;
          }
        }
        fallback[block + i] = why;
      }
      for (int64_t c = block; c < block_end; ++c) {
        if (fallback[c]) {
          out.fallback_cells.push_back(c);
        } else if (scratch.degenerate_count[c - block] > 0 || scratch.corner_count[c - block] > 0 ||
                   scratch.curve_count[c - block] > 0) {
          out.degenerate_points += scratch.degenerate_count[c - block];
          out.critical_corners += scratch.corner_count[c - block];
          out.critical_curves += scratch.curve_count[c - block];
          out.degenerate_slack =
              std::max(out.degenerate_slack, scratch.degenerate_slack[c - block]);
        }
      }
      const auto block_done = clock_type::now();
      out.critical_seconds += seconds_between(block_start, critical_done);
      out.connection_seconds += seconds_between(critical_done, block_done);
      block_start = block_done;
    }
  });
  return phase;
}

} // namespace hoct
