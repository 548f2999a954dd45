#include "mesh/mesh_checks.hpp"

#include "mesh/duplicate_points.hpp"
#include "poly/binomial.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"

#include "util/concurrent_sets.hpp"
#include "util/parallel_for.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>
#include <sstream>

namespace hoct {
namespace {

// Largest magnitude of a coordinate or value: the cell computations multiply a few of them
// (Jacobians, degree elevation, derivatives), which must stay finite in double precision.
constexpr double kMaxMagnitude = kMaxAbsValue;

std::string format_double(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The checks of point p: finite coordinates and value, within the magnitude the cell
// computations can multiply.
void check_point(const MeshInput &in, int64_t p, ProblemLog &problems) {
  const auto &x = in.points[p];
  if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    problems.add(Problem::NonFiniteCoordinate,
                 "point " + std::to_string(p) + " has a NaN or infinite coordinate");
  else if (std::abs(x[0]) > kMaxMagnitude || std::abs(x[1]) > kMaxMagnitude ||
           std::abs(x[2]) > kMaxMagnitude)
    problems.add(Problem::CoordinateOutOfRange,
                 "point " + std::to_string(p) + " has a coordinate beyond 1e100 in magnitude " +
                     "(products of coordinates would overflow double precision)");
  if (!std::isfinite(in.values[p]))
    problems.add(Problem::NonFiniteValue,
                 "point " + std::to_string(p) + " has value " + std::to_string(in.values[p]));
  else if (std::abs(in.values[p]) > kMaxMagnitude)
    problems.add(Problem::ValueOutOfRange,
                 "point " + std::to_string(p) + " has value " + format_double(in.values[p]) +
                     ", beyond 1e100 in magnitude (the Bernstein form and the root isolation "
                     "would overflow double precision; rescale the field)");
}

// The checks of cell c (`seen`: scratch): a supported degree with its number of nodes, node ids
// in range and distinct. False if the cell cannot be used at all.
bool check_cell(const MeshInput &in, int64_t c, std::vector<int64_t> &seen, ProblemLog &problems) {
  const int64_t np = static_cast<int64_t>(in.points.size());
  const int d = in.cell_degree[c];
  const int64_t n = in.cell_offsets[c + 1] - in.cell_offsets[c];
  const CellKind kind = in.kind(static_cast<std::size_t>(c));
  if (static_cast<uint8_t>(kind) > static_cast<uint8_t>(CellKind::SerendipityQuadrilateral)) {
    problems.add(Problem::BadCell, "cell " + std::to_string(c) + " has an unknown kind " +
                                       std::to_string(static_cast<int>(kind)));
    return false;
  }
  const bool quad = is_quadrilateral(kind);
  if (d < 1 || n != cell_node_count(kind, d) ||
      (kind == CellKind::SerendipityQuadrilateral && d < 2)) {
    problems.add(Problem::BadCell, "cell " + std::to_string(c) + " (" + cell_kind_name(kind) +
                                       ") has degree " + std::to_string(d) + " but " +
                                       std::to_string(n) + " nodes");
    return false;
  }
  // The conversions to Bernstein form (and the per-edge buffers of Field) stop at kMaxDegree; a
  // quadrilateral of bidegree (p, p) becomes triangles of degree 2p (mesh/cell_split).
  if ((quad ? 2 * d : d) > kMaxDegree) {
    problems.add(Problem::UnsupportedDegree,
                 "cell " + std::to_string(c) + " has degree " + std::to_string(d) + " (at most " +
                     std::to_string(quad ? kMaxDegree / 2 : kMaxDegree) + " supported for a " +
                     cell_kind_name(kind) + ")");
    return false;
  }
  bool ok = true;
  seen.assign(in.cell_nodes.begin() + in.cell_offsets[c],
              in.cell_nodes.begin() + in.cell_offsets[c + 1]);
  for (int64_t id : seen)
    if (id < 0 || id >= np) {
      problems.add(Problem::MissingNode, "cell " + std::to_string(c) + " refers to point " +
                                             std::to_string(id) + ", but there are " +
                                             std::to_string(np) + " points");
      ok = false;
      break;
    }
  std::sort(seen.begin(), seen.end());
  if (std::adjacent_find(seen.begin(), seen.end()) != seen.end())
    problems.add(Problem::InconsistentNodes,
                 "cell " + std::to_string(c) + " uses point " +
                     std::to_string(*std::adjacent_find(seen.begin(), seen.end())) +
                     " for two of its nodes");
  return ok;
}

} // namespace

bool check_input(const MeshInput &in, ProblemLog &problems, int threads) {
  bool ok = true;
  const int64_t np = static_cast<int64_t>(in.points.size());
  if (in.values.size() != in.points.size()) {
    problems.add(Problem::InconsistentArrays, std::to_string(in.points.size()) + " points but " +
                                                  std::to_string(in.values.size()) + " values");
    return false;
  }
  if (in.cell_offsets.size() != in.cell_degree.size() + 1 || in.cell_offsets.front() != 0 ||
      in.cell_offsets.back() != static_cast<int64_t>(in.cell_nodes.size())) {
    problems.add(Problem::InconsistentArrays, "cell offsets do not match the cells");
    return false;
  }
  if (in.cell_degree.empty()) {
    problems.add(Problem::EmptyMesh, "the mesh has no cells");
    return false;
  }
  // Points, then cells, in fixed blocks on threads (problems appended in block order).
  // The finite values' range in the same pass, per block (min and max are exact: the same
  // range on any thread count).
  const int64_t point_blocks = problem_blocks(np);
  BlockProblems point_problems(point_blocks);
  std::vector<std::array<double, 2>> block_range(static_cast<std::size_t>(point_blocks));
  parallel_chunks(np, point_blocks, threads_for(np, threads, 65536),
                  [&](int64_t block, int64_t begin, int64_t end, int) {
                    ProblemLog &log = point_problems[block];
                    double block_lo = INFINITY, block_hi = -INFINITY;
                    for (int64_t p = begin; p < end; ++p) {
                      check_point(in, p, log);
                      const double v = in.values[p];
                      if (std::isfinite(v)) {
                        block_lo = std::min(block_lo, v);
                        block_hi = std::max(block_hi, v);
                      }
                    }
                    block_range[block] = {block_lo, block_hi};
                  });
  point_problems.append_to(problems);
  double lo = INFINITY, hi = -INFINITY;
  for (const auto &[block_lo, block_hi] : block_range) {
    lo = std::min(lo, block_lo);
    hi = std::max(hi, block_hi);
  }
  if (hi > lo && hi - lo < kMinValueRange) {
    std::ostringstream m;
    m << "the values span only " << hi - lo << " (from " << lo << " to " << hi << "), less than "
      << kMinValueRange
      << ": products of derivatives would underflow and critical points be lost; rescale the "
         "field";
    problems.add(Problem::ValueRangeTooSmall, m.str());
  }
  const int64_t nc = static_cast<int64_t>(in.cell_degree.size());
  const int64_t cell_blocks = problem_blocks(nc);
  BlockProblems cell_problems(cell_blocks);
  std::atomic<bool> cells_ok{true};
  parallel_chunks(nc, cell_blocks, threads_for(nc, threads, 32768),
                  [&](int64_t block, int64_t begin, int64_t end, int) {
                    std::vector<int64_t> seen;
                    for (int64_t c = begin; c < end; ++c)
                      if (!check_cell(in, c, seen, cell_problems[block]))
                        cells_ok.store(false, std::memory_order_relaxed);
                  });
  cell_problems.append_to(problems);
  ok = ok && cells_ok.load();
  return ok && problems.count(Problem::InconsistentNodes) == 0;
}

namespace {

// Sample points: the lattice of degree m (including corners and edges).
template <class F> void for_each_sample(int m, F &&f) {
  for (int b = 0; b <= m; ++b)
    for (int a = 0; a <= m - b; ++a)
      f(static_cast<double>(a) / m, static_cast<double>(b) / m);
}

std::string cell_str(int64_t c) { return "cell " + std::to_string(c); }

} // namespace

void check_duplicate_vertices(const MeshInput &in, const Topology &topo, ProblemLog &problems,
                              int threads, const std::array<Vec3, 2> *box) {
  const int64_t nv = topo.num_vertices();
  std::vector<int64_t> corners(static_cast<std::size_t>(nv));
  parallel_for(nv, threads_for(nv, threads, 65536), [&](int64_t begin, int64_t end, int) {
    for (int64_t v = begin; v < end; ++v)
      corners[v] = topo.vertex_point(v);
  });
  const auto [lo, hi] = box ? *box : bounding_box(in.points, threads);
  const double tol = 1e-10 * std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const std::vector<int64_t> rep = coincident_points(in.points, corners, tol, threads);
  for (std::size_t i = 0; i < corners.size(); ++i)
    if (rep[i] != corners[i]) {
      const Vec3 &p = in.points[corners[i]];
      std::ostringstream m;
      m << "points " << rep[i] << " and " << corners[i] << " are at the same position (" << p[0]
        << ", " << p[1] << ", " << p[2]
        << ") but are different vertices: the cells around them are not connected there (a "
           "crack, holes or separate pieces). Merge them by position (hoct: --merge-duplicates)";
      problems.add(Problem::DuplicateVertices, m.str());
    }
}

namespace {

// The smallest and largest Bernstein coefficient, at degree 2q, of sum over pairs (i, j) of
// degree-q lattice points of pair(i, j) B_i B_j: a product of two degree-q polynomials, or a sum
// of such products, given by the products of their coefficients (q < kMaxDegree). Each
// coefficient is a convex combination of pair(i, j) values.
template <class Pair> std::pair<double, double> product_coefficient_range(int q, const Pair &pair) {
  constexpr int kMost = (2 * kMaxDegree - 1) * 2 * kMaxDegree / 2; // lattice_size(2 kMaxDegree - 2)
  double out[kMost];
  const int n = 2 * q, size = lattice_size(n);
  std::fill(out, out + size, 0.0);
  for (int b1 = 0; b1 <= q; ++b1)
    for (int a1 = 0; a1 <= q - b1; ++a1) {
      const int i = lattice_index(q, a1, b1);
      const double w1 = trinomial(q - a1 - b1, a1, b1);
      for (int b2 = 0; b2 <= q; ++b2)
        for (int a2 = 0; a2 <= q - b2; ++a2) {
          const int j = lattice_index(q, a2, b2);
          out[lattice_index(n, a1 + a2, b1 + b2)] +=
              w1 * trinomial(q - a2 - b2, a2, b2) * pair(i, j);
        }
    }
  double lo = INFINITY, hi = -INFINITY;
  for (int b = 0; b <= n; ++b)
    for (int a = 0; a <= n - b; ++a) {
      const double x = out[lattice_index(n, a, b)] / trinomial(n - a - b, a, b);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  return {lo, hi};
}

// Largest |component k| over n points.
double largest(const Vec3 *p, int n, int k) {
  double m = 0;
  for (int i = 0; i < n; ++i)
    m = std::max(m, std::abs(p[i][k]));
  return m;
}

// The sign of the Jacobian determinant of planar cell c (+1, -1, or 0 when it vanishes or changes
// sign inside the cell, which `problems` then records).
int planar_jacobian_sign(const Geometry &g, int64_t c, double area_tol, ProblemLog &problems) {
  if (g.is_linear(c)) {
    // Constant Jacobian: its determinant decides.
    const auto j = g.jacobian(c, 0, 0);
    const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    const int s = det > area_tol ? 1 : det < -area_tol ? -1 : 0;
    if (s == 0)
      problems.add(Problem::ZeroArea, cell_str(c) + " has zero area");
    return s;
  }
  // det J = x_u y_v - x_v y_u as a Bernstein polynomial of degree 2(p-1): where its coefficients
  // are all beyond area_tol (and their rounding, a few ulps of the factors' largest products,
  // far below the 1e-13 allowed for here), so is det J everywhere in the cell.
  {
    const int d = g.degree(c), q = d - 1, m = lattice_size(q);
    Vec3 du[lattice_size(kMaxDegree - 1)], dv[lattice_size(kMaxDegree - 1)];
    g.derivative_points(c, du, dv);
    const auto [lo, hi] = product_coefficient_range(
        q, [&](int i, int j) { return du[i][0] * dv[j][1] - dv[i][0] * du[j][1]; });
    const double rounding =
        1e-13 * (largest(du, m, 0) * largest(dv, m, 1) + largest(dv, m, 0) * largest(du, m, 1));
    if (lo > area_tol + rounding)
      return 1;
    if (hi < -area_tol - rounding)
      return -1;
  }
  // Not certified: det J in full, for its samples below.
  const BernsteinTriangle x = g.component(c, 0), y = g.component(c, 1);
  const BernsteinTriangle a = x.du() * y.dv(), b = x.dv() * y.du();
  std::vector<double> dc(a.coefficients().size());
  for (std::size_t i = 0; i < dc.size(); ++i)
    dc[i] = a.coefficients()[i] - b.coefficients()[i];
  const BernsteinTriangle dj(a.degree(), std::move(dc));
  auto [lo, hi] = dj.bounds();
  if (lo > area_tol)
    return 1;
  if (hi < -area_tol)
    return -1;
  // Not certified by the coefficients: sample densely.
  double smin = INFINITY, smax = -INFINITY;
  for_each_sample(std::max(4, 2 * g.degree(c)), [&](double u, double v) {
    const double val = dj(u, v);
    smin = std::min(smin, val);
    smax = std::max(smax, val);
  });
  if (smin > area_tol)
    return 1;
  if (smax < -area_tol)
    return -1;
  if (std::max(std::abs(smin), std::abs(smax)) <= area_tol)
    problems.add(Problem::ZeroArea, cell_str(c) + " has zero area");
  else
    problems.add(Problem::FoldedCell,
                 cell_str(c) + ": its Jacobian changes sign inside the cell (min " +
                     std::to_string(smin) + ", max " + std::to_string(smax) + ")");
  return 0;
}

// Surface cell c: n = phi_u x phi_v must not vanish nor flip inside it.
void check_surface_cell(const Geometry &g, int64_t c, double area_tol, ProblemLog &problems) {
  const int m = g.is_linear(c) ? 1 : std::max(4, 2 * g.degree(c));
  Vec3 n0{0, 0, 0};
  {
    const auto j = g.jacobian(c, 1.0 / 3, 1.0 / 3);
    n0 = {j[0][1] * j[1][2] - j[0][2] * j[1][1], j[0][2] * j[1][0] - j[0][0] * j[1][2],
          j[0][0] * j[1][1] - j[0][1] * j[1][0]};
  }
  if (!g.is_linear(c)) {
    // n . n0 = phi_u . (phi_v x n0) as a Bernstein polynomial of degree 2(p-1): where its
    // coefficients all exceed area_tol |n0| (and their rounding, a few ulps of the factors'
    // largest products, far below the 1e-13 allowed for here), so does n . n0 everywhere in
    // the cell, hence |n| > area_tol and no flip (what the samples below look for, certified at
    // once; most cells end here).
    const int d = g.degree(c), q = d - 1, m = lattice_size(q);
    Vec3 du[lattice_size(kMaxDegree - 1)], w[lattice_size(kMaxDegree - 1)];
    g.derivative_points(c, du, w);
    for (int i = 0; i < m; ++i) { // phi_v x n0
      const Vec3 v = w[i];
      w[i] = {v[1] * n0[2] - v[2] * n0[1], v[2] * n0[0] - v[0] * n0[2],
              v[0] * n0[1] - v[1] * n0[0]};
    }
    const auto [lo, hi] = product_coefficient_range(q, [&](int i, int j) {
      return du[i][0] * w[j][0] + du[i][1] * w[j][1] + du[i][2] * w[j][2];
    });
    double magnitude = 0;
    for (int k = 0; k < 3; ++k)
      magnitude += largest(du, m, k) * largest(w, m, k);
    const double n0_length = std::sqrt(n0[0] * n0[0] + n0[1] * n0[1] + n0[2] * n0[2]);
    if (lo > area_tol * n0_length + 1e-13 * magnitude)
      return;
  }
  bool degenerate = false, folded = false;
  for_each_sample(m, [&](double u, double v) {
    const auto j = g.jacobian(c, u, v);
    const Vec3 n = {j[0][1] * j[1][2] - j[0][2] * j[1][1], j[0][2] * j[1][0] - j[0][0] * j[1][2],
                    j[0][0] * j[1][1] - j[0][1] * j[1][0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len <= area_tol)
      degenerate = true;
    else if (n[0] * n0[0] + n[1] * n0[1] + n[2] * n0[2] <= 0)
      folded = true;
  });
  if (degenerate)
    problems.add(Problem::ZeroArea,
                 cell_str(c) + " has zero area at some point (its map is singular)");
  else if (folded)
    problems.add(Problem::FoldedCell, cell_str(c) + ": its surface normal flips inside the cell");
}

// The control points of cell c's map along its local edge k, from the edge's lo to its hi
// vertex, raised to degree `to` (into out: to + 1 points).
void edge_control_points(const Geometry &g, const Topology &topo, int64_t c, int k, int to,
                         Vec3 *out) {
  const int d = g.degree(c);
  const Vec3 *cp = g.control_points(c);
  const bool reversed = topo.edge_reversed(c, k);
  for (int t = 0; t <= d; ++t)
    out[reversed ? d - t : t] = cp[edge_lattice_index(d, k, t)];
  for (int n = d; n < to; ++n) { // degree n -> n + 1, in place from the end
    out[n + 1] = out[n];
    for (int i = n; i >= 1; --i) {
      const double a = static_cast<double>(i) / (n + 1);
      for (int j = 0; j < 3; ++j)
        out[i][j] = a * out[i - 1][j] + (1 - a) * out[i][j];
    }
  }
}

} // namespace

void check_edge_geometry(const Geometry &g, const Topology &topo, ProblemLog &problems,
                         int threads) {
  const int64_t ne = topo.num_edges();
  const std::array<Vec3, 2> &box = g.bounds();
  double magnitude = 0;
  for (const Vec3 &corner : box)
    for (int j = 0; j < 3; ++j)
      magnitude = std::max(magnitude, std::abs(corner[j]));
  const double tol = 1e-6 * (g.extent() + magnitude);
  const int64_t blocks = problem_blocks(ne);
  BlockProblems found(blocks);
  parallel_chunks(
      ne, blocks, threads_for(ne, threads, 65536), [&](int64_t b, int64_t begin, int64_t end, int) {
        Vec3 first[kMaxDegree + 1], other[kMaxDegree + 1];
        for (int64_t e = begin; e < end; ++e) {
          const int n = topo.edge_cell_count(e);
          if (n < 2)
            continue;
          const int64_t *cells = topo.edge_cells_begin(e);
          int to = 1;
          for (int i = 0; i < n; ++i)
            to = std::max(to, g.degree(cells[i]));
          if (to == 1)
            continue; // straight segments between the same two vertices
          edge_control_points(g, topo, cells[0], topo.local_edge(cells[0], e), to, first);
          for (int i = 1; i < n; ++i) {
            edge_control_points(g, topo, cells[i], topo.local_edge(cells[i], e), to, other);
            double gap = 0;
            for (int t = 0; t <= to; ++t)
              for (int j = 0; j < 3; ++j)
                gap = std::max(gap, std::abs(other[t][j] - first[t][j]));
            if (!(gap <= tol)) {
              const auto &v = topo.edge_vertices(e);
              std::ostringstream m;
              m << "cells " << cells[0] << " (degree " << g.degree(cells[0]) << " map) and "
                << cells[i] << " (degree " << g.degree(cells[i])
                << " map) do not meet along their shared edge (points " << topo.vertex_point(v[0])
                << "-" << topo.vertex_point(v[1]) << "): their edge curves differ by up to " << gap
                << " (a curved edge next to a straight one, or edge nodes at "
                   "different positions: the mesh has a gap there)";
              found[b].add(Problem::GeometricGap, m.str());
            }
          }
        }
      });
  found.append_to(problems);
}

namespace {} // namespace

void check_geometry(const Geometry &g, const Topology &topo, ProblemLog &problems, int threads) {
  const int64_t nc = g.num_cells();
  const double ext = std::max(g.extent(), 1e-300);
  const double area_tol = 1e-12 * ext * ext;
  // Cells in fixed blocks on threads, problems appended in block order.
  const int64_t blocks = problem_blocks(nc);
  const int cell_threads = threads_for(nc, threads, 32768);
  BlockProblems found(blocks);
  if (!g.planar()) {
    parallel_chunks(nc, blocks, cell_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
      for (int64_t c = begin; c < end; ++c)
        check_surface_cell(g, c, area_tol, found[b]);
    });
    found.append_to(problems);
    return;
  }
  // Signs relative to a consistent orientation; the minority orientation is inverted.
  UninitializedVector<int8_t> sign(static_cast<std::size_t>(nc));
  std::vector<int64_t> positive(static_cast<std::size_t>(blocks), 0), negative(positive);
  parallel_chunks(nc, blocks, cell_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
    int64_t pos = 0, neg = 0; // counted here, stored once (the blocks' slots share lines)
    for (int64_t c = begin; c < end; ++c) {
      const int s = planar_jacobian_sign(g, c, area_tol, found[b]);
      sign[c] = static_cast<int8_t>(s * (topo.orientable() ? topo.cell_parity(c) : 1));
      pos += sign[c] > 0;
      neg += sign[c] < 0;
    }
    positive[b] = pos;
    negative[b] = neg;
  });
  found.append_to(problems);
  const int64_t pos = std::accumulate(positive.begin(), positive.end(), int64_t{0});
  const int64_t neg = std::accumulate(negative.begin(), negative.end(), int64_t{0});
  if (pos > 0 && neg > 0) {
    // The minority orientation of each component (connected across two-cell edges): each
    // component's parities are relative to its own first cell, and separate components may be
    // listed either way round without overlapping (a piece of a partitioned mesh in two parts,
    // two separate squares).
    ConcurrentSets parts(nc, cell_threads);
    const int64_t ne = topo.num_edges();
    parallel_for(ne, threads_for(ne, threads, 65536), [&](int64_t begin, int64_t end, int) {
      for (int64_t e = begin; e < end; ++e)
        if (topo.edge_cell_count(e) == 2)
          parts.unite(topo.edge_cells_begin(e)[0], topo.edge_cells_begin(e)[1]);
    });
    std::vector<int64_t> balance(static_cast<std::size_t>(nc), 0); // by root: pos - neg, and 0
    std::vector<int64_t> root(static_cast<std::size_t>(nc));
    for (int64_t c = 0; c < nc; ++c) {
      root[c] = parts.find(c);
      balance[root[c]] += sign[c];
    }
    // As before within a component: the minority is the negative sign unless it outnumbers.
    auto minority = [&](int64_t c) { return balance[root[c]] >= 0 ? int8_t{-1} : int8_t{1}; };
    BlockProblems inverted(blocks);
    parallel_chunks(nc, blocks, cell_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
      for (int64_t c = begin; c < end; ++c)
        if (sign[c] == minority(c))
          inverted[b].add(Problem::InvertedCell,
                          cell_str(c) + " is inverted (its orientation disagrees with its "
                                        "neighbours': the mesh overlaps itself)");
    });
    inverted.append_to(problems);
  }
}

} // namespace hoct
