#include "datasets/linear_mesh.hpp"

#include "datasets/seeded_random.hpp"
#include "poly/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace hoct {

LinearMesh square_grid(int nx, int ny, double h, double x0, double y0, double jitter, uint64_t seed,
                       const std::function<bool(int, int)> &keep) {
  LinearMesh m;
  auto id = [&](int i, int j) { return static_cast<int64_t>(j) * (nx + 1) + i; };
  std::vector<std::array<int64_t, 3>> tris;
  std::vector<int> use((nx + 1) * (ny + 1), 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (keep && !keep(i, j))
        continue;
      const int64_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        tris.push_back({a, b, c});
        tris.push_back({a, c, d});
      } else {
        tris.push_back({a, b, d});
        tris.push_back({b, c, d});
      }
      for (int64_t v : {a, b, c, d})
        ++use[v];
    }
  // A vertex is interior if all four squares around it are kept.
  auto kept = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < nx && j < ny && (!keep || keep(i, j));
  };
  SeededRandom rng(seed);
  std::vector<int64_t> new_id((nx + 1) * (ny + 1), -1);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double jx = rng.uniform(-1, 1), jy = rng.uniform(-1, 1); // drawn for every vertex
      if (!use[id(i, j)])
        continue;
      const bool interior = kept(i - 1, j - 1) && kept(i, j - 1) && kept(i - 1, j) && kept(i, j);
      const double dx = interior ? jitter * h * jx : 0, dy = interior ? jitter * h * jy : 0;
      new_id[id(i, j)] = static_cast<int64_t>(m.vertices.size());
      m.vertices.push_back({x0 + i * h + dx, y0 + j * h + dy, 0.0});
    }
  for (const auto &t : tris)
    m.triangles.push_back({new_id[t[0]], new_id[t[1]], new_id[t[2]]});
  return m;
}

LinearMesh icosphere(int n) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> c = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  LinearMesh m;
  // Vertices keyed by their exact lattice description: corner, edge (sorted corners, step),
  // or face interior, so shared points are created once.
  std::map<std::array<int, 4>, int64_t> index;
  auto normalize = [](Vec3 p) {
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return Vec3{p[0] / r, p[1] / r, p[2] / r};
  };
  for (int f = 0; f < 20; ++f) {
    const int A = faces[f][0], B = faces[f][1], C = faces[f][2];
    auto vertex = [&](int i, int j) {
      // Key: a corner; an icosahedron edge (its corners ascending, the weight of the first);
      // or a face-interior point (face, i, j). Shared points get one id.
      const int k = n - i - j;
      std::array<std::pair<int, int>, 3> w = {{{A, k}, {B, i}, {C, j}}};
      std::sort(w.begin(), w.end());
      std::array<std::pair<int, int>, 3> nz{};
      int cnt = 0;
      for (const auto &x : w)
        if (x.second > 0)
          nz[cnt++] = x;
      std::array<int, 4> key;
      if (cnt == 1)
        key = {nz[0].first, -1, -1, -1};
      else if (cnt == 2)
        key = {nz[0].first, nz[1].first, nz[0].second, -1};
      else
        key = {f + 1000, i, j, -2};
      auto it = index.find(key);
      if (it != index.end())
        return it->second;
      Vec3 p;
      for (int a = 0; a < 3; ++a)
        p[a] = (c[A][a] * k + c[B][a] * i + c[C][a] * j) / n;
      m.vertices.push_back(normalize(p));
      return index[key] = static_cast<int64_t>(m.vertices.size() - 1);
    };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        m.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i, j + 1)});
        if (i + j + 1 < n)
          m.triangles.push_back({vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
      }
  }
  return m;
}

MeshInput lagrange_mesh(const LinearMesh &lm, int d, const Placement &place,
                        const ScalarFunction &f) {
  MeshInput m;
  const int64_t nv = static_cast<int64_t>(lm.vertices.size());
  const int64_t nt = static_cast<int64_t>(lm.triangles.size());
  // Edges by sorting (lo, hi, triangle, local) once.
  struct Rec {
    int64_t lo, hi, tri;
    int local;
  };
  std::vector<Rec> rec;
  rec.reserve(static_cast<std::size_t>(3 * nt));
  for (int64_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int64_t a = lm.triangles[t][k], b = lm.triangles[t][(k + 1) % 3];
      rec.push_back({std::min(a, b), std::max(a, b), t, k});
    }
  std::sort(rec.begin(), rec.end(), [](const Rec &x, const Rec &y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.tri < y.tri);
  });
  std::vector<std::array<int64_t, 3>> tri_edge(nt);
  std::vector<std::array<int64_t, 2>> edges;
  for (std::size_t i = 0; i < rec.size(); ++i) {
    if (i == 0 || rec[i].lo != rec[i - 1].lo || rec[i].hi != rec[i - 1].hi)
      edges.push_back({rec[i].lo, rec[i].hi});
    tri_edge[rec[i].tri][rec[i].local] = static_cast<int64_t>(edges.size() - 1);
  }
  const int64_t ne = static_cast<int64_t>(edges.size());
  const int per_edge = d - 1, per_cell = (d - 1) * (d - 2) / 2;
  const int64_t np = nv + ne * per_edge + nt * per_cell;
  m.points.resize(np);
  m.values.resize(np);
  auto set = [&](int64_t id, const Vec3 &flat) {
    m.points[id] = place ? place(flat) : flat;
    m.values[id] = f(m.points[id]);
  };
  for (int64_t v = 0; v < nv; ++v)
    set(v, lm.vertices[v]);
  for (int64_t e = 0; e < ne; ++e)
    for (int s = 1; s < d; ++s) {
      const Vec3 &a = lm.vertices[edges[e][0]], &b = lm.vertices[edges[e][1]];
      Vec3 p;
      for (int k = 0; k < 3; ++k)
        p[k] = a[k] + (b[k] - a[k]) * s / d;
      set(nv + e * per_edge + (s - 1), p);
    }
  m.cell_nodes.reserve(static_cast<std::size_t>(nt) * lattice_size(d));
  m.cell_offsets.reserve(nt + 1);
  m.cell_degree.reserve(nt);
  std::vector<int64_t> nodes(lattice_size(d));
  for (int64_t t = 0; t < nt; ++t) {
    const auto &tri = lm.triangles[t];
    for (int k = 0; k < 3; ++k)
      nodes[corner_index(d, k)] = tri[k];
    for (int k = 0; k < 3; ++k) {
      const int64_t e = tri_edge[t][k];
      const bool forward = tri[k] == edges[e][0];
      for (int s = 1; s < d; ++s)
        nodes[edge_lattice_index(d, k, s)] = nv + e * per_edge + (forward ? s - 1 : d - 1 - s);
    }
    int interior = 0;
    for (int b = 1; b < d; ++b)
      for (int a = 1; a + b < d; ++a) {
        const int64_t id = nv + ne * per_edge + t * per_cell + interior++;
        const double u = static_cast<double>(a) / d, v = static_cast<double>(b) / d;
        Vec3 p;
        for (int k = 0; k < 3; ++k)
          p[k] = (1 - u - v) * lm.vertices[tri[0]][k] + u * lm.vertices[tri[1]][k] +
                 v * lm.vertices[tri[2]][k];
        set(id, p);
        nodes[lattice_index(d, a, b)] = id;
      }
    m.add_cell(d, nodes.data());
  }
  return m;
}

} // namespace hoct
