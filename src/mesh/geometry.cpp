#include "mesh/geometry.hpp"

#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"

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

Geometry Geometry::build(const MeshInput &in) {
  Geometry g;
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  if (!in.points.empty()) {
    g.bounds_ = {in.points[0], in.points[0]};
    for (const auto &p : in.points)
      for (int i = 0; i < 3; ++i) {
        g.bounds_[0][i] = std::min(g.bounds_[0][i], p[i]);
        g.bounds_[1][i] = std::max(g.bounds_[1][i], p[i]);
      }
  }
  const double ext = g.extent();
  const double tol = 1e-12 * std::max(ext, 1e-300);
  g.planar_ = g.bounds_[1][2] - g.bounds_[0][2] <= tol;

  g.degree_.resize(nc);
  g.offset_.assign(nc + 1, 0);
  g.coef_.reserve(3 * static_cast<std::size_t>(nc)); // straight cells: three control points each
  std::vector<Vec3> ctrl;
  // The lattice positions (u, v) of the degree in use (one degree in most meshes).
  int table_degree = 0;
  std::vector<std::array<double, 2>> uv;
  for (int64_t c = 0; c < nc; ++c) {
    const int d = in.cell_degree[c];
    const int n = lattice_size(d);
    const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
    const Vec3 &p0 = in.points[nodes[corner_index(d, 0)]];
    const Vec3 &p1 = in.points[nodes[corner_index(d, 1)]];
    const Vec3 &p2 = in.points[nodes[corner_index(d, 2)]];
    if (d != table_degree) {
      uv.resize(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        const auto q = lattice_point(d, i);
        uv[i] = {static_cast<double>(q[0]) / d, static_cast<double>(q[1]) / d};
      }
      table_degree = d;
    }
    // Linear if every point of the lattice (nodes, or control points) is the affine image of its
    // lattice position. The nodes are tested first: a straight cell needs no conversion.
    auto affine = [&](auto point) {
      for (int i = 0; i < n; ++i) {
        const double u = uv[i][0], v = uv[i][1];
        const Vec3 &q = point(i);
        for (int a = 0; a < 3; ++a)
          if (std::abs(q[a] - ((1 - u - v) * p0[a] + u * p1[a] + v * p2[a])) > tol)
            return false;
      }
      return true;
    };
    bool linear = d == 1 || affine([&](int i) -> const Vec3 & { return in.points[nodes[i]]; });
    if (!linear) {
      ctrl.assign(n, Vec3{0, 0, 0});
      const auto &m = lagrange_to_bernstein_triangle(d);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const double w = m[static_cast<std::size_t>(i) * n + j];
          const Vec3 &p = in.points[nodes[j]];
          for (int a = 0; a < 3; ++a)
            ctrl[i][a] += w * p[a];
        }
      linear = affine([&](int i) -> const Vec3 & { return ctrl[i]; });
    }
    if (linear) {
      g.coef_.push_back(p0);
      g.coef_.push_back(p1);
      g.coef_.push_back(p2);
      g.degree_[c] = 1;
    } else {
      g.coef_.insert(g.coef_.end(), ctrl.begin(), ctrl.end());
      g.degree_[c] = static_cast<uint8_t>(d);
      ++g.curved_cells_;
    }
    g.offset_[c + 1] = static_cast<int64_t>(g.coef_.size());
  }
  return g;
}

BernsteinTriangle Geometry::component(int64_t c, int i) const {
  std::vector<double> v;
  v.reserve(static_cast<std::size_t>(offset_[c + 1] - offset_[c]));
  for (int64_t k = offset_[c]; k < offset_[c + 1]; ++k)
    v.push_back(coef_[k][i]);
  return BernsteinTriangle(degree_[c], std::move(v));
}

Vec3 Geometry::position(int64_t c, double u, double v) const {
  if (degree_[c] == 1) {
    const Vec3 *p = &coef_[offset_[c]];
    Vec3 r;
    for (int a = 0; a < 3; ++a)
      r[a] = (1 - u - v) * p[0][a] + u * p[1][a] + v * p[2][a];
    return r;
  }
  // de Casteljau on the control points themselves (no temporaries for the three components).
  const std::size_t n = static_cast<std::size_t>(offset_[c + 1] - offset_[c]);
  Vec3 buf[kStackPoints];
  std::vector<Vec3> heap;
  Vec3 *w = buf;
  if (n > kStackPoints) {
    heap.resize(n);
    w = heap.data();
  }
  std::copy(coef_.begin() + offset_[c], coef_.begin() + offset_[c + 1], w);
  return casteljau3(w, degree_[c], u, v);
}

std::array<Vec3, 2> Geometry::jacobian(int64_t c, double u, double v) const {
  // Control points of d phi/du and d phi/dv (degree d-1), then de Casteljau.
  const int d = degree_[c];
  const Vec3 *p = &coef_[offset_[c]];
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
  for (int b = 0; b <= d - 1; ++b)
    for (int a = 0; a <= d - 1 - b; ++a)
      for (int k = 0; k < 3; ++k) {
        const double base = p[lattice_index(d, a, b)][k];
        wu[lattice_index(d - 1, a, b)][k] = d * (p[lattice_index(d, a + 1, b)][k] - base);
        wv[lattice_index(d - 1, a, b)][k] = d * (p[lattice_index(d, a, b + 1)][k] - base);
      }
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
