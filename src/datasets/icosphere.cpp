#include "datasets/icosphere.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace hoct {

LinearMesh icosphere(int n) {
  if (n < 1)
    throw Error("icosphere: subdivision must be at least 1");
  const double t = (1 + std::sqrt(5.0)) / 2, s = 1 / std::sqrt(1 + t * t);
  const double corner[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  int face[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  LinearMesh m;
  for (const auto &c : corner)
    m.vertices.push_back({c[0] * s, c[1] * s, c[2] * s});
  // Orient every face outward (normal . centroid > 0): the base solid is convex.
  for (auto &f : face) {
    const Vec3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    const Vec3 u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
               v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3 nrm = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                      u[0] * v[1] - u[1] * v[0]};
    if (nrm[0] * (a[0] + b[0] + c[0]) + nrm[1] * (a[1] + b[1] + c[1]) +
            nrm[2] * (a[2] + b[2] + c[2]) <
        0)
      std::swap(f[1], f[2]);
  }
  auto point = [&](int a, int b, int c, int i, int j) { // lattice point (i, j) of face (a, b, c)
    const double wa = static_cast<double>(n - i - j) / n, wb = static_cast<double>(i) / n,
                 wc = static_cast<double>(j) / n;
    Vec3 p;
    for (int k = 0; k < 3; ++k)
      p[k] = wa * m.vertices[a][k] + wb * m.vertices[b][k] + wc * m.vertices[c][k];
    return p;
  };
  // Points inside icosahedron edges: created once per edge, from its lower corner.
  std::map<std::pair<int, int>, int64_t> edge_first;
  for (const auto &f : face)
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(f[k], f[(k + 1) % 3]), b = std::max(f[k], f[(k + 1) % 3]);
      if (n < 2 || edge_first.count({a, b}))
        continue;
      edge_first[{a, b}] = static_cast<int64_t>(m.vertices.size());
      for (int step = 1; step < n; ++step)
        m.vertices.push_back(point(a, b, b, step, 0));
    }
  std::vector<int64_t> local(static_cast<std::size_t>((n + 1) * (n + 2) / 2));
  for (const auto &f : face) {
    const int A = f[0], B = f[1], C = f[2];
    auto at = [&](int i, int j) -> int64_t & { return local[j * (n + 1) - j * (j - 1) / 2 + i]; };
    // Ids of the face's lattice points: corners, edge points (from whichever corner is lower),
    // then new interior points.
    auto edge_point = [&](int p, int q, int step) { // step from p towards q
      const int a = std::min(p, q);
      const auto it = edge_first.find({a, std::max(p, q)});
      return it->second + (p == a ? step : n - step) - 1;
    };
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        const int k = n - i - j;
        if (i == 0 && j == 0)
          at(i, j) = A;
        else if (k == 0 && j == 0)
          at(i, j) = B;
        else if (k == 0 && i == 0)
          at(i, j) = C;
        else if (j == 0)
          at(i, j) = edge_point(A, B, i);
        else if (k == 0)
          at(i, j) = edge_point(B, C, j);
        else if (i == 0)
          at(i, j) = edge_point(A, C, j);
        else {
          at(i, j) = static_cast<int64_t>(m.vertices.size());
          m.vertices.push_back(point(A, B, C, i, j));
        }
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < n)
          m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return m;
}

int icosphere_subdivision(long long cells) {
  int n = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(cells) / 20.0))));
  const auto miss = [cells](long long k) { return std::llabs(20 * k * k - cells); };
  return miss(n + 1) < miss(n) ? n + 1 : n;
}

} // namespace hoct
