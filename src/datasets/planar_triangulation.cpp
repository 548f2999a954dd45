#include "datasets/planar_triangulation.hpp"

#include "datasets/seeded_random.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hoct {

LinearMesh grid_triangulation(const GridSpec &g) {
  if (g.nx < 1 || g.ny < 1 || !(g.hx > 0) || !(g.hy > 0))
    throw Error("grid triangulation: need at least one rectangle of positive size");
  const int64_t nx = g.nx, ny = g.ny;
  auto kept = [&](int64_t i, int64_t j) {
    return i >= 0 && j >= 0 && i < nx && j < ny && (!g.keep || g.keep(int(i), int(j)));
  };
  auto grid_id = [&](int64_t i, int64_t j) { return j * (nx + 1) + i; };
  // Which grid vertices are used, and their ids in the result.
  std::vector<int64_t> id(static_cast<std::size_t>((nx + 1) * (ny + 1)), -1);
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i)
      if (kept(i, j))
        for (int64_t v :
             {grid_id(i, j), grid_id(i + 1, j), grid_id(i, j + 1), grid_id(i + 1, j + 1)})
          id[v] = 0;
  LinearMesh m;
  SeededRandom rng(g.seed, 1);
  const double amplitude = g.jitter * std::min(g.hx, g.hy);
  for (int64_t j = 0; j <= ny; ++j)
    for (int64_t i = 0; i <= nx; ++i) {
      // Drawn for every grid vertex, so the jitter of a vertex does not depend on the holes.
      const double jx = rng.uniform(-1, 1), jy = rng.uniform(-1, 1);
      if (id[grid_id(i, j)] < 0)
        continue;
      const bool interior = kept(i - 1, j - 1) && kept(i, j - 1) && kept(i - 1, j) && kept(i, j);
      id[grid_id(i, j)] = static_cast<int64_t>(m.vertices.size());
      m.vertices.push_back({g.x0 + static_cast<double>(i) * g.hx + (interior ? amplitude * jx : 0),
                            g.y0 + static_cast<double>(j) * g.hy + (interior ? amplitude * jy : 0),
                            0.0});
    }
  SeededRandom diagonal(g.seed, 2);
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i) {
      const bool rising = diagonal.next() >> 63; // drawn for every rectangle
      if (!kept(i, j))
        continue;
      const int64_t a = id[grid_id(i, j)], b = id[grid_id(i + 1, j)], c = id[grid_id(i + 1, j + 1)],
                    d = id[grid_id(i, j + 1)];
      if (rising) { // diagonal a-c
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else { // diagonal b-d
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  return m;
}

LinearMesh ring_disk(int rings, double radius, const Vec3 &centre, double jitter, uint64_t seed) {
  if (rings < 1 || !(radius > 0))
    throw Error("ring disk: need at least one ring and a positive radius");
  const int64_t n = rings;
  auto ring_start = [](int64_t k) { return k == 0 ? 0 : 1 + 3 * k * (k - 1); };
  // Vertex m (mod 6k) of ring k.
  auto vertex = [&](int64_t k, int64_t m) { return k == 0 ? 0 : ring_start(k) + m % (6 * k); };
  LinearMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(ring_start(n + 1)));
  SeededRandom rng(seed, 1);
  const double amplitude = jitter * radius / static_cast<double>(n);
  for (int64_t k = 0; k <= n; ++k)
    for (int64_t m = 0; m < std::max<int64_t>(1, 6 * k); ++m) {
      const double jx = rng.uniform(-1, 1), jy = rng.uniform(-1, 1);
      const double a = k == 0 ? 0.0 : 2 * std::numbers::pi * static_cast<double>(m) / (6.0 * k);
      const double r = radius * static_cast<double>(k) / static_cast<double>(n);
      const double jit = k < n ? amplitude : 0.0;
      mesh.vertices.push_back({centre[0] + r * std::cos(a) + jit * jx,
                               centre[1] + r * std::sin(a) + jit * jy, centre[2]});
    }
  // Between rings k-1 and k, sector s (one sixth): k triangles with an edge on ring k, k-1 with
  // an edge on ring k-1. Angles grow with m, so these are counter-clockwise.
  for (int64_t k = 1; k <= n; ++k)
    for (int64_t s = 0; s < 6; ++s) {
      for (int64_t j = 0; j < k; ++j)
        mesh.triangles.push_back(
            {vertex(k, s * k + j), vertex(k, s * k + j + 1), vertex(k - 1, s * (k - 1) + j)});
      for (int64_t j = 0; j + 1 < k; ++j)
        mesh.triangles.push_back({vertex(k - 1, s * (k - 1) + j), vertex(k, s * k + j + 1),
                                  vertex(k - 1, s * (k - 1) + j + 1)});
    }
  return mesh;
}

} // namespace hoct
