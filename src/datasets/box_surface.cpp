#include "datasets/box_surface.hpp"

#include "util/error.hpp"

#include <array>
#include <unordered_map>
#include <utility>

namespace hoct {

LinearMesh box_surface(int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1)
    throw Error("box surface: need at least one interval per axis");
  const std::array<int64_t, 3> n = {nx, ny, nz};
  LinearMesh m;
  std::unordered_map<int64_t, int64_t> id; // grid point (i, j, k) -> vertex id
  auto vertex = [&](const std::array<int64_t, 3> &g) {
    const int64_t key = (g[0] * (n[1] + 1) + g[1]) * (n[2] + 1) + g[2];
    const auto [it, fresh] = id.try_emplace(key, static_cast<int64_t>(m.vertices.size()));
    if (fresh)
      m.vertices.push_back({-1.0 + 2.0 * static_cast<double>(g[0]) / static_cast<double>(n[0]),
                            -1.0 + 2.0 * static_cast<double>(g[1]) / static_cast<double>(n[1]),
                            -1.0 + 2.0 * static_cast<double>(g[2]) / static_cast<double>(n[2])});
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      // Face axis a at -1 (side 0) or +1 (side 1); (b, c) cyclic after a, so e_b x e_c = e_a.
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (int64_t j = 0; j < n[c]; ++j)
        for (int64_t i = 0; i < n[b]; ++i) {
          auto at = [&](int64_t di, int64_t dj) {
            std::array<int64_t, 3> g{};
            g[a] = side ? n[a] : 0;
            g[b] = i + di;
            g[c] = j + dj;
            return vertex(g);
          };
          const int64_t p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          std::array<std::array<int64_t, 3>, 2> t;
          if ((i + j) % 2 == 0)
            t = {{{p00, p10, p11}, {p00, p11, p01}}};
          else
            t = {{{p00, p10, p01}, {p10, p11, p01}}};
          for (auto tri : t) {
            if (!side) // the -1 face: outward is -e_a
              std::swap(tri[1], tri[2]);
            m.triangles.push_back(tri);
          }
        }
    }
  return m;
}

} // namespace hoct
