#include "mesh/geometry.hpp"

#include "mesh/duplicate_points.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {

namespace {

// de Casteljau on 3D control points of degree d (canonical lattice order), in place in w.
Vec3 casteljau3(Vec3 *w, int d, double u, double v) {
  const double l0 = 1 - u - v;
  for (int m = d; m > 0; --m)
    for (int b = 0; b <= m - 1; ++b)
      for (int a = 0; a <= m - 1 - b; ++a) {
        Vec3 &out = w[lattice_index(m - 1, a, b)];
        const Vec3 &p0 = w[lattice_index(m, a, b)], &p1 = w[lattice_index(m, a + 1, b)],
                   &p2 = w[lattice_index(m, a, b + 1)];
        for (int k = 0; k < 3; ++k)
          out[k] = l0 * p0[k] + u * p1[k] + v * p2[k];
      }
  return w[0];
}

constexpr std::size_t kStackPoints = 91; // lattice_size(12)

} // namespace

double Geometry::extent() const {
  double s = 0;
  for (int i = 0; i < 3; ++i)
    s += (bounds_[1][i] - bounds_[0][i]) * (bounds_[1][i] - bounds_[0][i]);
  return std::sqrt(s);
}

namespace {

// Converts cells' Lagrange nodes to control points, with the lattice positions of the degree in
// use (one degree in most meshes) and a buffer kept from cell to cell.
class CellMapper {
public:
  CellMapper(const MeshInput &in, double tol) : in_(in), tol_(tol) {}

  // The degree of cell c's map: 1 when every node (or control point) is the affine image of its
  // lattice position; else the smallest k in {2, 3} dividing the input degree d for which every
  // node is, within the tolerance, the degree-k interpolant of the nodes on the degree-k
  // sub-lattice (a quadrilateral's half, mesh/cell_split: a bilinear map restricted to a
  // triangle, quadratic, carried by triangles of degree 2p); else d. Low-degree maps make the
  // Jacobian checks and evaluations cheap.
  int degree(int64_t c) {
    setup(c);
    if (d_ == 1 || affine([&](int i) -> const Vec3 & { return in_.points[nodes_[i]]; }))
      return 1;
    for (int k = 2; k <= 3 && k < d_; ++k)
      if (d_ % k == 0 && of_degree(k))
        return k;
    convert();
    return affine([&](int i) -> const Vec3 & { return ctrl_[i]; }) ? 1 : d_;
  }

  // Writes cell c's control points for a map of degree `degree` (from degree()).
  void control_points(int64_t c, int degree, Vec3 *out) {
    setup(c);
    if (degree == 1) {
      out[0] = *p_[0];
      out[1] = *p_[1];
      out[2] = *p_[2];
      return;
    }
    if (degree < d_) {
      sub_lattice_control_points(degree);
      std::copy(sub_.begin(), sub_.end(), out);
      return;
    }
    convert();
    std::copy(ctrl_.begin(), ctrl_.end(), out);
  }

private:
  void setup(int64_t c) {
    d_ = in_.cell_degree[c];
    n_ = lattice_size(d_);
    nodes_ = &in_.cell_nodes[in_.cell_offsets[c]];
    for (int k = 0; k < 3; ++k)
      p_[k] = &in_.points[nodes_[corner_index(d_, k)]];
    if (d_ != table_degree_) {
      uv_.resize(static_cast<std::size_t>(n_));
      for (int i = 0; i < n_; ++i) {
        const auto q = lattice_point(d_, i);
        uv_[i] = {static_cast<double>(q[0]) / d_, static_cast<double>(q[1]) / d_};
      }
      table_degree_ = d_;
    }
  }
  template <class Point> bool affine(const Point &point) const {
    for (int i = 0; i < n_; ++i) {
      const double u = uv_[i][0], v = uv_[i][1];
      const Vec3 &q = point(i);
      for (int a = 0; a < 3; ++a)
        if (std::abs(q[a] - ((1 - u - v) * (*p_[0])[a] + u * (*p_[1])[a] + v * (*p_[2])[a])) > tol_)
          return false;
    }
    return true;
  }
  void convert() {
    ctrl_.assign(static_cast<std::size_t>(n_), Vec3{0, 0, 0});
    const auto &m = lagrange_to_bernstein_triangle(d_);
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) {
        const double w = m[static_cast<std::size_t>(i) * n_ + j];
        const Vec3 &p = in_.points[nodes_[j]];
        for (int a = 0; a < 3; ++a)
          ctrl_[i][a] += w * p[a];
      }
  }

  // The control points of degree k (dividing d_) through the nodes at the degree-k sub-lattice.
  void sub_lattice_control_points(int k) {
    const int m = lattice_size(k), step = d_ / k;
    const auto &L = lagrange_to_bernstein_triangle(k);
    sub_.assign(static_cast<std::size_t>(m), Vec3{0, 0, 0});
    for (int j = 0; j < m; ++j) {
      const auto q = lattice_point(k, j);
      const Vec3 &p = in_.points[nodes_[lattice_index(d_, q[0] * step, q[1] * step)]];
      for (int i = 0; i < m; ++i)
        for (int a = 0; a < 3; ++a)
          sub_[static_cast<std::size_t>(i)][a] += L[static_cast<std::size_t>(i) * m + j] * p[a];
    }
  }
  // Every node within the tolerance of the degree-k map through the sub-lattice nodes: the
  // degree-k Lagrange interpolant of those nodes evaluated at the others (the sub-lattice nodes
  // reproduce themselves), stopping at the first that is off.
  bool of_degree(int k) {
    const Interpolation &w = interpolation(k);
    const int m = lattice_size(k);
    for (const int i : w.others) {
      const double *row = &w.weights[static_cast<std::size_t>(i) * m];
      Vec3 x{0, 0, 0};
      for (int j = 0; j < m; ++j) {
        const Vec3 &p = in_.points[nodes_[w.sub[static_cast<std::size_t>(j)]]];
        for (int a = 0; a < 3; ++a)
          x[a] += row[j] * p[a];
      }
      const Vec3 &q = in_.points[nodes_[i]];
      for (int a = 0; a < 3; ++a)
        if (!(std::abs(q[a] - x[a]) <= tol_))
          return false;
    }
    return true;
  }
  // For the degree in use: the degree-k Lagrange basis at the degree-d_ lattice points (row per
  // node), the nodes on the degree-k sub-lattice (in its lattice order) and the other nodes.
  struct Interpolation {
    std::vector<double> weights;
    std::vector<int> sub, others;
  };
  const Interpolation &interpolation(int k) {
    Interpolation &w = interpolation_[k];
    if (interpolation_degree_[k] == d_)
      return w;
    const int m = lattice_size(k), step = d_ / k;
    const std::vector<double> &L = lagrange_to_bernstein_triangle(k);
    w.weights.assign(static_cast<std::size_t>(n_) * m, 0.0);
    for (int i = 0; i < n_; ++i)
      for (int l = 0; l < m; ++l) {
        // B_l^k at node i, by de Casteljau on the unit control values.
        std::vector<Vec3> unit(static_cast<std::size_t>(m), Vec3{0, 0, 0});
        unit[static_cast<std::size_t>(l)] = {1, 0, 0};
        const double b = casteljau3(unit.data(), k, uv_[i][0], uv_[i][1])[0];
        for (int j = 0; j < m; ++j)
          w.weights[static_cast<std::size_t>(i) * m + j] +=
              b * L[static_cast<std::size_t>(l) * m + j];
      }
    std::vector<bool> on_sub(static_cast<std::size_t>(n_), false);
    w.sub.resize(static_cast<std::size_t>(m));
    for (int j = 0; j < m; ++j) {
      const auto q = lattice_point(k, j);
      w.sub[static_cast<std::size_t>(j)] = lattice_index(d_, q[0] * step, q[1] * step);
      on_sub[static_cast<std::size_t>(w.sub[static_cast<std::size_t>(j)])] = true;
    }
    w.others.clear();
    for (int i = 0; i < n_; ++i)
      if (!on_sub[static_cast<std::size_t>(i)])
        w.others.push_back(i);
    interpolation_degree_[k] = d_;
    return w;
  }

  const MeshInput &in_;
  const double tol_;
  std::vector<Vec3> sub_;
  Interpolation interpolation_[4];
  int interpolation_degree_[4] = {0, 0, 0, 0};
  int d_ = 0, n_ = 0, table_degree_ = 0;
  const int64_t *nodes_ = nullptr;
  const Vec3 *p_[3] = {nullptr, nullptr, nullptr};
  std::vector<std::array<double, 2>> uv_;
  std::vector<Vec3> ctrl_;
};

} // namespace

Geometry Geometry::build(const MeshInput &in, int threads, const std::array<Vec3, 2> *box) {
  Geometry g;
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  if (!in.points.empty())
    g.bounds_ = box ? *box : bounding_box(in.points, threads);
  const double ext = g.extent();
  // Straight within 1e-12 of the extent, or within the coordinates' own rounding (float32
  // files: a straight cell's edge nodes are rounded off the line by ~1e-7 of their magnitude).
  double magnitude = 0;
  for (const Vec3 &corner : g.bounds_)
    for (int a = 0; a < 3; ++a)
      magnitude = std::max(magnitude, std::abs(corner[a]));
  const double tol =
      std::max(1e-12 * std::max(ext, 1e-300), 8 * in.coordinate_precision * magnitude);
  g.planar_ = g.bounds_[1][2] - g.bounds_[0][2] <= tol;

  // Each cell's map degree (1: straight, three control points), then the control points into
  // their slots: two passes over the cells in parallel, a curved cell converted in each.
  auto maps = std::make_shared<Maps>();
  UninitializedVector<uint8_t> &degree = maps->degree;
  UninitializedVector<int64_t> &offset = maps->offset;
  UninitializedVector<Vec3> &coef = maps->coef;
  degree.resize(nc);
  const int workers = threads_for(nc, std::max(1, threads), 4096);
  // Curved cells counted per worker and summed (a count: the same for any split of the cells).
  std::vector<int64_t> curved(static_cast<std::size_t>(workers), 0);
  parallel_for(nc, workers, [&](int64_t begin, int64_t end, int worker) {
    CellMapper mapper(in, tol);
    int64_t here = 0;
    for (int64_t c = begin; c < end; ++c) {
      degree[c] = static_cast<uint8_t>(mapper.degree(c));
      here += degree[c] != 1;
    }
    curved[static_cast<std::size_t>(worker)] += here;
  });
  for (const int64_t n : curved)
    g.curved_cells_ += n;
  offset.resize(nc + 1);
  parallel_offsets(nc, threads, offset, [&](int64_t c) { return lattice_size(degree[c]); });
  coef.resize(static_cast<std::size_t>(offset[nc]));
  parallel_for(nc, workers, [&](int64_t begin, int64_t end, int) {
    CellMapper mapper(in, tol);
    for (int64_t c = begin; c < end; ++c)
      mapper.control_points(c, degree[c], &coef[offset[c]]);
  });
  g.maps_ = std::move(maps);
  return g;
}

BernsteinTriangle Geometry::component(int64_t c, int i) const {
  const Maps &m = *maps_;
  std::vector<double> v;
  v.reserve(static_cast<std::size_t>(m.offset[c + 1] - m.offset[c]));
  for (int64_t k = m.offset[c]; k < m.offset[c + 1]; ++k)
    v.push_back(m.coef[k][i]);
  return BernsteinTriangle(m.degree[c], std::move(v));
}

Vec3 Geometry::position(int64_t c, double u, double v) const {
  const Maps &m = *maps_;
  if (m.degree[c] == 1) {
    const Vec3 *p = &m.coef[m.offset[c]];
    Vec3 r;
    for (int a = 0; a < 3; ++a)
      r[a] = (1 - u - v) * p[0][a] + u * p[1][a] + v * p[2][a];
    return r;
  }
  // de Casteljau on the control points themselves (no temporaries for the three components).
  const std::size_t n = static_cast<std::size_t>(m.offset[c + 1] - m.offset[c]);
  Vec3 buf[kStackPoints];
  std::vector<Vec3> heap;
  Vec3 *w = buf;
  if (n > kStackPoints) {
    heap.resize(n);
    w = heap.data();
  }
  std::copy(m.coef.begin() + m.offset[c], m.coef.begin() + m.offset[c + 1], w);
  return casteljau3(w, m.degree[c], u, v);
}

void Geometry::derivative_points(int64_t c, Vec3 *du, Vec3 *dv) const {
  const Maps &m = *maps_;
  const int d = m.degree[c];
  const Vec3 *p = &m.coef[m.offset[c]];
  for (int b = 0; b <= d - 1; ++b)
    for (int a = 0; a <= d - 1 - b; ++a)
      for (int k = 0; k < 3; ++k) {
        const double base = p[lattice_index(d, a, b)][k];
        du[lattice_index(d - 1, a, b)][k] = d * (p[lattice_index(d, a + 1, b)][k] - base);
        dv[lattice_index(d - 1, a, b)][k] = d * (p[lattice_index(d, a, b + 1)][k] - base);
      }
}

std::array<Vec3, 2> Geometry::jacobian(int64_t c, double u, double v) const {
  const Maps &m = *maps_;
  // Control points of d phi/du and d phi/dv (degree d-1), then de Casteljau.
  const int d = m.degree[c];
  const std::size_t n = static_cast<std::size_t>(lattice_size(d - 1));
  Vec3 bu[kStackPoints], bv[kStackPoints];
  std::vector<Vec3> hu, hv;
  Vec3 *wu = bu, *wv = bv;
  if (n > kStackPoints) {
    hu.resize(n);
    hv.resize(n);
    wu = hu.data();
    wv = hv.data();
  }
  derivative_points(c, wu, wv);
  return {casteljau3(wu, d - 1, u, v), casteljau3(wv, d - 1, u, v)};
}

Mat2 Geometry::frame(int64_t c) const {
  const auto [a, b] = jacobian(c, 1.0 / 3, 1.0 / 3);
  const double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  const double na = std::sqrt(aa);
  if (!(na > 0))
    return {{{0, 0}, {0, 0}}};
  const double r01 = ab / na;
  return {{{na, r01}, {0, std::sqrt(std::max(bb - r01 * r01, 0.0))}}};
}

} // namespace hoct
