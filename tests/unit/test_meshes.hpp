// Small meshes built directly in tests (independent of the dataset generators): a perturbed grid
// on the unit square and an octahedral sphere, of any degree, with shared edge nodes.
#pragma once

#include "mesh/mesh_input.hpp"
#include "poly/lattice.hpp"

#include <cmath>
#include <functional>
#include <map>
#include <random>

namespace hoct::testing {

// Builds a degree-d Lagrange mesh from linear triangles (vertex positions + triangles), placing
// higher-order nodes with `place` (flat position -> final position) and values from `value`
// (or random values if `value` is empty). Edge nodes are created once per edge and shared.
// `rotate` cyclically rotates each cell's corners randomly (to mix edge orientations).
inline MeshInput lagrange_mesh(const std::vector<Vec3> &verts,
                               const std::vector<std::array<int64_t, 3>> &tris,
                               const std::function<int(int64_t)> &degree_of,
                               const std::function<Vec3(const Vec3 &)> &place,
                               const std::function<double(const Vec3 &)> &value,
                               std::mt19937_64 &rng, bool rotate = true) {
  MeshInput m;
  std::uniform_real_distribution<double> U(-1, 1);
  auto add_point = [&](const Vec3 &flat) {
    const Vec3 p = place ? place(flat) : flat;
    m.points.push_back(p);
    m.values.push_back(value ? value(p) : U(rng));
    return static_cast<int64_t>(m.points.size() - 1);
  };
  std::vector<int64_t> vid;
  for (const auto &v : verts)
    vid.push_back(add_point(v));
  std::map<std::tuple<int64_t, int64_t, int>, std::vector<int64_t>> edge_nodes;
  for (std::size_t c = 0; c < tris.size(); ++c) {
    auto t = tris[c];
    if (rotate) {
      const int r = static_cast<int>(rng() % 3);
      std::rotate(t.begin(), t.begin() + r, t.end());
    }
    const int d = degree_of(static_cast<int64_t>(c));
    std::vector<int64_t> nodes(lattice_size(d), -1);
    for (int k = 0; k < 3; ++k)
      nodes[corner_index(d, k)] = vid[t[k]];
    for (int k = 0; k < 3; ++k) {
      const int64_t a = t[k], b = t[(k + 1) % 3];
      const int64_t lo = std::min(a, b), hi = std::max(a, b);
      auto &en = edge_nodes[{lo, hi, d}];
      if (en.empty())
        for (int s = 1; s < d; ++s) {
          Vec3 p;
          for (int i = 0; i < 3; ++i)
            p[i] = verts[lo][i] + (verts[hi][i] - verts[lo][i]) * s / d;
          en.push_back(add_point(p));
        }
      for (int s = 1; s < d; ++s)
        nodes[edge_lattice_index(d, k, s)] = a == lo ? en[s - 1] : en[d - 1 - s];
    }
    for (int i = 0; i < lattice_size(d); ++i)
      if (nodes[i] < 0) {
        const auto q = lattice_point(d, i);
        const double u = static_cast<double>(q[0]) / d, v = static_cast<double>(q[1]) / d;
        Vec3 p;
        for (int j = 0; j < 3; ++j)
          p[j] = (1 - u - v) * verts[t[0]][j] + u * verts[t[1]][j] + v * verts[t[2]][j];
        nodes[i] = add_point(p);
      }
    m.add_cell(d, nodes.data());
  }
  // (Appended: GCC 12 warns falsely (-Wrestrict) on assigning these literals at -O3.)
  m.source.append("test mesh");
  m.field_name.push_back('f');
  return m;
}

// n x n squares on [0,1]^2, each split in two, counter-clockwise; interior vertices jittered.
inline void square_grid(int n, std::mt19937_64 &rng, std::vector<Vec3> &verts,
                        std::vector<std::array<int64_t, 3>> &tris) {
  std::uniform_real_distribution<double> J(-0.2 / n, 0.2 / n);
  verts.clear();
  tris.clear();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      verts.push_back({static_cast<double>(i) / n + (inner ? J(rng) : 0.0),
                       static_cast<double>(j) / n + (inner ? J(rng) : 0.0), 0.0});
    }
  auto id = [&](int i, int j) { return static_cast<int64_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
}

// The same grid with its vertices on the lattice (no jitter): the lines x = i / n and y = j / n
// are lines of mesh edges. Degree `degree`, values f(x, y); cells' corners rotated by `seed`.
inline MeshInput lattice_grid(int n, int degree, const std::function<double(double, double)> &f,
                              uint64_t seed = 3) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  square_grid(n, rng, v, t);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      v[static_cast<std::size_t>(j * (n + 1) + i)] = {static_cast<double>(i) / n,
                                                      static_cast<double>(j) / n, 0};
  return lagrange_mesh(
      v, t, [degree](int64_t) { return degree; }, nullptr,
      [&f](const Vec3 &p) { return f(p[0], p[1]); }, rng);
}

// Octahedron with each face split into k^2 triangles, vertices projected to the unit sphere by
// the `place` callback of lagrange_mesh (pass sphere_projection). Outward oriented.
inline void octahedron(int k, std::vector<Vec3> &verts, std::vector<std::array<int64_t, 3>> &tris) {
  verts.clear();
  tris.clear();
  const Vec3 c[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  const int faces[8][3] = {{0, 1, 2}, {1, 3, 2}, {3, 4, 2}, {4, 0, 2},
                           {1, 0, 5}, {3, 1, 5}, {4, 3, 5}, {0, 4, 5}};
  std::map<std::array<long long, 3>, int64_t> index;
  auto vertex = [&](const Vec3 &p) {
    const std::array<long long, 3> key = {std::llround(p[0] * 1e9), std::llround(p[1] * 1e9),
                                          std::llround(p[2] * 1e9)};
    auto it = index.find(key);
    if (it != index.end())
      return it->second;
    verts.push_back(p);
    return index[key] = static_cast<int64_t>(verts.size() - 1);
  };
  for (const auto &f : faces) {
    auto at = [&](int i, int j) {
      Vec3 p;
      for (int a = 0; a < 3; ++a)
        p[a] = c[f[0]][a] + (c[f[1]][a] - c[f[0]][a]) * i / k + (c[f[2]][a] - c[f[0]][a]) * j / k;
      return vertex(p);
    };
    for (int j = 0; j < k; ++j)
      for (int i = 0; i + j < k; ++i) {
        tris.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < k)
          tris.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
}

inline Vec3 sphere_projection(const Vec3 &p) {
  const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {p[0] / r, p[1] / r, p[2] / r};
}

// Linear triangles of an nu x nv grid of quadrilaterals (two triangles each): flat on the
// integer lattice, or wrapped in u (a band around a circle; twisted once for a Moebius strip,
// whose v runs across the band) and also in v (a torus), on the surface in 3D; values from
// `value` at the points.
inline MeshInput surface_grid(int nu, int nv, bool wrap_u, bool wrap_v, bool twist,
                              const std::function<double(const Vec3 &)> &value) {
  MeshInput in;
  const int rows = wrap_v ? nv : nv + 1, cols = wrap_u ? nu : nu + 1;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const double u = 2 * M_PI * i / nu, w = 2 * M_PI * j / nv;
      if (wrap_u && wrap_v) {
        in.points.push_back({(2 + 0.7 * std::cos(w)) * std::cos(u),
                             (2 + 0.7 * std::cos(w)) * std::sin(u), 0.7 * std::sin(w)});
      } else if (wrap_u) {
        const double s = (j - nv / 2.0) / nv;
        in.points.push_back({(2 + s * std::cos(u / 2)) * std::cos(u),
                             (2 + s * std::cos(u / 2)) * std::sin(u), s * std::sin(u / 2)});
      } else {
        in.points.push_back({static_cast<double>(i), static_cast<double>(j), 0});
      }
      in.values.push_back(value(in.points.back()));
    }
  auto id = [&](int i, int j) {
    if (wrap_u && i == nu && twist) // the seam of the twist: across it, v runs the other way
      return static_cast<int64_t>((nv - j) * cols);
    return static_cast<int64_t>((j % rows) * cols + i % cols);
  };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int64_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const int64_t t1[3] = {a, b, c}, t2[3] = {a, c, d};
      in.add_cell(1, t1);
      in.add_cell(1, t2);
    }
  return in;
}

} // namespace hoct::testing
