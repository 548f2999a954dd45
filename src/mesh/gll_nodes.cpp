#include "mesh/gll_nodes.hpp"

#include "mesh/mesh_fingerprint.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"
#include "poly/quad_basis.hpp"
#include "poly/sample_fit.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace hoct {

std::vector<double> gll_points(int d) {
  // The interior points are the roots of P_d'(x) on [-1, 1]: Newton from the Chebyshev-Gauss-
  // Lobatto points on (1 - x^2) P_d'(x) = d (P_{d-1}(x) - x P_d(x)).
  std::vector<double> t(static_cast<std::size_t>(d) + 1);
  for (int k = 0; k <= d; ++k) {
    double x = -std::cos(M_PI * k / d);
    if (k > 0 && k < d)
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = x; // P_0, P_1, then P_{n-1}, P_n
        for (int n = 2; n <= d; ++n) {
          const double p2 = ((2 * n - 1) * x * p1 - (n - 1) * p0) / n;
          p0 = p1;
          p1 = p2;
        }
        // f = P_{d-1} - x P_d (zero where P_d' is), f' = -d P_d... via (1 - x^2) P_d'' etc.:
        // Newton on g(x) = (1 - x^2) P_d'(x) / d = P_{d-1} - x P_d, g' = -(d + 1) P_d.
        const double g = p0 - x * p1, dg = -(d + 1) * p1;
        const double step = g / dg;
        x -= step;
        if (std::abs(step) < 1e-16)
          break;
      }
    t[k] = (x + 1) / 2;
  }
  t.front() = 0;
  t.back() = 1;
  return t;
}

namespace {

// The reference position (u, v) of point q in the straight triangle p0, p1, p2 (least squares
// in its plane) and q's distance from that plane; false for a degenerate triangle.
bool reference_position(const Vec3 &p0, const Vec3 &p1, const Vec3 &p2, const Vec3 &q, Vec2 &uv,
                        double &off_plane) {
  Vec3 e1, e2, r;
  for (int a = 0; a < 3; ++a) {
    e1[a] = p1[a] - p0[a];
    e2[a] = p2[a] - p0[a];
    r[a] = q[a] - p0[a];
  }
  auto dot = [](const Vec3 &x, const Vec3 &y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2);
  const double det = a11 * a22 - a12 * a12;
  if (!(det > 1e-24 * a11 * a22))
    return false;
  const double b1 = dot(e1, r), b2 = dot(e2, r);
  uv = {(a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det};
  Vec3 rest;
  for (int a = 0; a < 3; ++a)
    rest[a] = r[a] - uv[0] * e1[a] - uv[1] * e2[a];
  off_plane = std::sqrt(dot(rest, rest));
  return true;
}

// M[i (p + 1) + a] = L_a(i / p), L_a the Lagrange basis of the GLL points g of degree p: values
// at the GLL points to values at the equispaced ones (the ends exactly).
std::vector<double> gll_to_equispaced(const std::vector<double> &g) {
  const int p = static_cast<int>(g.size()) - 1;
  std::vector<double> m(static_cast<std::size_t>((p + 1) * (p + 1)), 0.0);
  for (int i = 0; i <= p; ++i)
    for (int a = 0; a <= p; ++a) {
      long double w = 1.0L;
      for (int k = 0; k <= p; ++k)
        if (k != a)
          w *= (static_cast<long double>(i) / p - g[k]) / (static_cast<long double>(g[a]) - g[k]);
      m[static_cast<std::size_t>(i * (p + 1) + a)] = static_cast<double>(w);
    }
  for (int i = 0; i <= p; i += p)
    for (int a = 0; a <= p; ++a)
      m[static_cast<std::size_t>(i * (p + 1) + a)] = (i == 0 ? a == 0 : a == p) ? 1.0 : 0.0;
  return m;
}

// A node's new value and position, written once every one is computed from the old values.
struct NodeUpdate {
  int64_t id;
  double value;
  Vec3 x;
};

// An edge's inner nodes (`ids`: its p + 1 nodes from one end to the other) at the equispaced
// points: their values interpolated through the GLL nodes; their positions on the straight edge
// between its ends (`straight`), else interpolated too. Computed from the end of lower point id
// whichever cell or process asks: every cell around the edge, in any piece of a partitioned
// mesh, gives the same bits.
void resample_edge(const MeshInput &in, std::vector<int64_t> ids, const std::vector<double> &m,
                   bool straight, std::vector<NodeUpdate> &out) {
  if (ids.front() > ids.back())
    std::reverse(ids.begin(), ids.end());
  const int p = static_cast<int>(ids.size()) - 1;
  const Vec3 &x0 = in.points[static_cast<std::size_t>(ids.front())],
             &x1 = in.points[static_cast<std::size_t>(ids.back())];
  for (int t = 1; t < p; ++t) {
    double f = 0;
    Vec3 x{0, 0, 0};
    for (int a = 0; a <= p; ++a) {
      const double w = m[static_cast<std::size_t>(t * (p + 1) + a)];
      const auto id = static_cast<std::size_t>(ids[static_cast<std::size_t>(a)]);
      f += w * in.values[id];
      if (!straight)
        for (int k = 0; k < 3; ++k)
          x[k] += w * in.points[id][k];
    }
    if (straight) {
      const double s = double(t) / p;
      for (int k = 0; k < 3; ++k)
        x[k] = (1 - s) * x0[k] + s * x1[k];
    }
    out.push_back({ids[static_cast<std::size_t>(t)], f, x});
  }
}

void apply_updates(MeshInput &in, const std::vector<NodeUpdate> &updates) {
  for (const NodeUpdate &u : updates) {
    in.values[static_cast<std::size_t>(u.id)] = u.value;
    in.points[static_cast<std::size_t>(u.id)] = u.x;
  }
}

// Quadrilaterals of order p >= 3 whose edge nodes sit at the GLL points of their straight edges:
// their node values and positions replaced by those of their tensor interpolant (1D Lagrange
// through the GLL points, in each direction) at the equispaced nodes. An edge node's depend on
// its edge's nodes alone (resample_edge).
int64_t resample_gll_quadrilaterals(MeshInput &in) {
  constexpr double kTol = 1e-6;
  const std::size_t nc = in.num_cells();
  std::vector<std::vector<double>> gll_of(kMaxQuadDegree + 1), to_equi(kMaxQuadDegree + 1);
  std::vector<std::size_t> cells;
  for (std::size_t c = 0; c < nc; ++c) {
    const int p = in.cell_degree[c];
    if (in.kind(c) != CellKind::LagrangeQuadrilateral || p < 3 || p > kMaxQuadDegree)
      continue;
    if (gll_of[p].empty())
      gll_of[p] = gll_points(p);
    const std::vector<double> &g = gll_of[p];
    const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
    auto at = [&](int i, int j) -> const Vec3 & { return in.points[nodes[i + (p + 1) * j]]; };
    bool ok = true;
    // Edges (0,0)-(p,0), (p,0)-(p,p), (0,p)-(p,p), (0,0)-(0,p), nodes along increasing index.
    for (int e = 0; e < 4 && ok; ++e)
      for (int t = 1; t < p && ok; ++t) {
        auto node = [&](int k) -> const Vec3 & {
          return e == 0 ? at(k, 0) : e == 1 ? at(p, k) : e == 2 ? at(k, p) : at(0, k);
        };
        const Vec3 &a = node(0), &b = node(p), &x = node(t);
        double ab = 0, ax = 0, len2 = 0;
        for (int k = 0; k < 3; ++k) {
          ab += (b[k] - a[k]) * (x[k] - a[k]);
          len2 += (b[k] - a[k]) * (b[k] - a[k]);
        }
        if (!(len2 > 0)) {
          ok = false;
          break;
        }
        const double s = ab / len2;
        for (int k = 0; k < 3; ++k) {
          const double off = x[k] - a[k] - s * (b[k] - a[k]);
          ax += off * off;
        }
        ok = std::abs(s - g[static_cast<std::size_t>(t)]) <= kTol &&
             std::sqrt(ax) <= kTol * std::sqrt(len2);
      }
    if (ok)
      cells.push_back(c);
  }
  if (cells.empty())
    return 0;
  for (int p = 3; p <= kMaxQuadDegree; ++p)
    if (!gll_of[p].empty())
      to_equi[p] = gll_to_equispaced(gll_of[p]);
  std::vector<NodeUpdate> updates;
  std::vector<int64_t> edge;
  for (const std::size_t c : cells) {
    const int p = in.cell_degree[c], n = p + 1;
    const std::vector<double> &m = to_equi[p];
    const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
    for (int e = 0; e < 4; ++e) {
      edge.clear();
      for (int k = 0; k <= p; ++k)
        edge.push_back(e == 0   ? nodes[k]
                       : e == 1 ? nodes[p + n * k]
                       : e == 2 ? nodes[k + n * p]
                                : nodes[n * k]);
      resample_edge(in, edge, m, /*straight=*/false, updates);
    }
    for (int j = 1; j < p; ++j)
      for (int i = 1; i < p; ++i) {
        double f = 0;
        Vec3 x{0, 0, 0};
        for (int b = 0; b <= p; ++b)
          for (int a = 0; a <= p; ++a) {
            const double w =
                m[static_cast<std::size_t>(i * n + a)] * m[static_cast<std::size_t>(j * n + b)];
            if (w == 0)
              continue;
            const auto id = static_cast<std::size_t>(nodes[a + n * b]);
            f += w * in.values[id];
            for (int k = 0; k < 3; ++k)
              x[k] += w * in.points[id][k];
          }
        updates.push_back({nodes[i + n * j], f, x});
      }
  }
  if (!in.read_fingerprint)
    in.read_fingerprint = mesh_fingerprint(in);
  apply_updates(in, updates);
  return static_cast<int64_t>(cells.size());
}

} // namespace

GllResampling resample_gll_cells(MeshInput &in) {
  GllResampling r;
  if (!in.lagrange_triangles_only()) {
    // Triangles' GLL placement is recognised on meshes of Lagrange triangles only.
    r.quadrilaterals = resample_gll_quadrilaterals(in);
    return r;
  }
  const std::size_t nc = in.num_cells();
  // Most meshes have no cell of degree 3 or more: nothing to look at (and no per-cell arrays).
  if (std::none_of(in.cell_degree.begin(), in.cell_degree.end(), [](uint8_t d) { return d >= 3; }))
    return r;
  // The GLL cells and their nodes' reference positions.
  std::vector<std::pair<std::size_t, std::vector<Vec2>>> found;
  std::vector<std::vector<double>> gll_of(kMaxDegree + 1);
  constexpr double kTol = 1e-6;
  for (std::size_t c = 0; c < nc; ++c) {
    const int d = in.cell_degree[c];
    if (d < 3)
      continue;
    if (gll_of[d].empty())
      gll_of[d] = gll_points(d);
    const std::vector<double> &g = gll_of[d];
    const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
    const Vec3 &p0 = in.points[nodes[corner_index(d, 0)]],
               &p1 = in.points[nodes[corner_index(d, 1)]],
               &p2 = in.points[nodes[corner_index(d, 2)]];
    const double size =
        std::sqrt((p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1]) +
                  (p1[2] - p0[2]) * (p1[2] - p0[2]));
    // Most files' cells are equispaced: the first node of edge 0 tells at once.
    {
      Vec2 first;
      double off = 0;
      if (!reference_position(p0, p1, p2, in.points[nodes[1]], first, off) ||
          std::abs(first[0] - g[1]) > kTol || std::abs(first[1]) > kTol || off > kTol * size)
        continue;
    }
    const int n = lattice_size(d);
    std::vector<Vec2> uv(static_cast<std::size_t>(n));
    bool equispaced = true, ok = true;
    for (int i = 0; i < n && ok; ++i) {
      double off = 0;
      if (!reference_position(p0, p1, p2, in.points[nodes[i]], uv[i], off) || off > kTol * size) {
        ok = false; // degenerate, or curved out of its plane
        break;
      }
      const auto [a, b] = lattice_point(d, i);
      const double u = uv[i][0], v = uv[i][1];
      if (std::abs(u - double(a) / d) > kTol || std::abs(v - double(b) / d) > kTol)
        equispaced = false;
      if (b == 0 || a == 0 || a + b == d) { // an edge node: at the GLL points of its edge
        ok = std::abs(u - (b == 0 || a + b == d ? g[a] : 0.0)) <= kTol &&
             std::abs(v - (a == 0 || a + b == d ? g[b] : 0.0)) <= kTol;
      } else { // inside
        ok = u > kTol && v > kTol && u + v < 1 - kTol;
      }
    }
    if (ok && !equispaced) {
      found.emplace_back(c, std::move(uv));
      ++r.cells;
    }
  }
  if (r.cells == 0)
    return r;
  // Each GLL cell at its equispaced lattice: the edges' nodes by resample_edge (on the straight
  // edges), the inner ones from the polynomial through all its samples (their values at their
  // reference positions), on the straight triangle's lattice.
  std::vector<std::vector<double>> to_equi(kMaxDegree + 1);
  std::vector<NodeUpdate> updates;
  std::vector<int64_t> edge;
  std::vector<double> values;
  for (const auto &[c, positions] : found) {
    const int d = in.cell_degree[c];
    if (to_equi[d].empty())
      to_equi[d] = gll_to_equispaced(gll_of[d]);
    const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
    for (int k = 0; k < 3; ++k) {
      edge.clear();
      for (int t = 0; t <= d; ++t)
        edge.push_back(nodes[edge_lattice_index(d, k, t)]);
      resample_edge(in, edge, to_equi[d], /*straight=*/true, updates);
    }
    const int n = lattice_size(d);
    values.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      values[i] = in.values[nodes[i]];
    BernsteinTriangle poly;
    try {
      poly = bernstein_from_samples(positions, values, d);
    } catch (const Error &e) {
      throw Error(in.source + ": cell " + std::to_string(c) +
                  ": its nodes at Gauss-Lobatto-Legendre points give no polynomial: " + e.what());
    }
    const Vec3 p0 = in.points[nodes[corner_index(d, 0)]], p1 = in.points[nodes[corner_index(d, 1)]],
               p2 = in.points[nodes[corner_index(d, 2)]];
    for (int i = 0; i < n; ++i) {
      const auto [a, b] = lattice_point(d, i);
      if (a == 0 || b == 0 || a + b == d)
        continue; // a corner or an edge node
      const double u = double(a) / d, v = double(b) / d;
      Vec3 x;
      for (int k = 0; k < 3; ++k)
        x[k] = (1 - u - v) * p0[k] + u * p1[k] + v * p2[k];
      updates.push_back({nodes[i], poly(u, v), x});
    }
  }
  if (!in.read_fingerprint)
    in.read_fingerprint = mesh_fingerprint(in);
  apply_updates(in, updates);
  return r;
}

std::vector<std::string> gll_notes(const GllResampling &g) {
  std::vector<std::string> notes;
  if (g.cells > 0)
    notes.push_back(std::to_string(g.cells) +
                    " cell(s) have their nodes at Gauss-Lobatto-Legendre points (as DOLFINx "
                    "writes degree >= 3), though VTK's Lagrange cells label them as equispaced: "
                    "read as the polynomial through their values at those points");
  if (g.quadrilaterals > 0)
    notes.push_back(std::to_string(g.quadrilaterals) +
                    " quadrilateral(s) have their nodes at Gauss-Lobatto-Legendre points (as "
                    "DOLFINx writes order >= 3), though VTK's Lagrange cells label them as "
                    "equispaced: read as the polynomial through those points");
  return notes;
}

} // namespace hoct
