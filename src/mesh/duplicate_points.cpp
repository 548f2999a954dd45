#include "mesh/duplicate_points.hpp"

#include "error.hpp"
#include "tree/union_find.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace hoct {

double bounding_box_diagonal(const std::vector<Vec3> &points) {
  if (points.empty())
    return 0;
  Vec3 lo = points[0], hi = points[0];
  for (const auto &p : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

std::vector<int64_t> coincident_points(const std::vector<Vec3> &points,
                                       const std::vector<int64_t> &candidates, double tolerance) {
  const std::size_t n = candidates.size();
  std::vector<int64_t> result(candidates.begin(), candidates.end());
  if (n < 2 || !(tolerance > 0) || !std::isfinite(tolerance))
    return result;
  Vec3 lo = points[candidates[0]];
  for (int64_t c : candidates)
    for (int i = 0; i < 3; ++i)
      lo[i] = std::min(lo[i], points[c][i]);
  // Grid cells of size h = tolerance: close points lie in the same or adjacent cells.
  using Key = std::array<int64_t, 3>;
  auto key_of = [&](const Vec3 &p) {
    Key k;
    for (int i = 0; i < 3; ++i) {
      const double q = std::floor((p[i] - lo[i]) / tolerance);
      k[i] = q < 4e18 ? static_cast<int64_t>(q) : int64_t{4000000000000000000};
    }
    return k;
  };
  std::vector<std::pair<Key, std::size_t>> sorted(n);
  for (std::size_t i = 0; i < n; ++i)
    sorted[i] = {key_of(points[candidates[i]]), i};
  std::sort(sorted.begin(), sorted.end());
  UnionFind uf(n);
  const double tol2 = tolerance * tolerance;
  for (std::size_t s = 0; s < n; ++s) {
    const auto &[key, i] = sorted[s];
    const Vec3 &p = points[candidates[i]];
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Key k = {key[0] + dx, key[1] + dy, key[2] + dz};
          auto it =
              std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(k, std::size_t{0}));
          for (; it != sorted.end() && it->first == k; ++it) {
            const std::size_t j = it->second;
            if (j == i)
              continue;
            const Vec3 &q = points[candidates[j]];
            const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                              (p[2] - q[2]) * (p[2] - q[2]);
            if (d2 <= tol2)
              uf.unite(static_cast<int64_t>(i), static_cast<int64_t>(j));
          }
        }
  }
  std::vector<int64_t> smallest(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    int64_t &m = smallest[uf.find(static_cast<int64_t>(i))];
    if (m < 0 || candidates[i] < m)
      m = candidates[i];
  }
  for (std::size_t i = 0; i < n; ++i)
    result[i] = smallest[uf.find(static_cast<int64_t>(i))];
  return result;
}

MergeReport merge_duplicate_points(MeshInput &input, double relative_tolerance) {
  MergeReport r;
  const std::size_t np = input.points.size();
  std::vector<int64_t> all(np);
  for (std::size_t i = 0; i < np; ++i)
    all[i] = static_cast<int64_t>(i);
  const double tol = relative_tolerance * bounding_box_diagonal(input.points);
  const std::vector<int64_t> rep = coincident_points(input.points, all, tol);
  double scale = 0;
  for (double v : input.values)
    if (std::isfinite(v))
      scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < np && i < input.values.size(); ++i) {
    if (rep[i] == static_cast<int64_t>(i))
      continue;
    ++r.merged_points;
    const double a = input.values[rep[i]], b = input.values[i];
    if (!(std::abs(a - b) <= 1e-9 * scale)) {
      std::ostringstream m;
      m.precision(17);
      m << input.source << ": points " << rep[i] << " and " << i
        << " are at the same position but have values " << a << " and " << b
        << ": the field is discontinuous there, they are not merged";
      throw Error(m.str());
    }
  }
  for (auto &id : input.cell_nodes)
    if (id >= 0 && id < static_cast<int64_t>(np))
      id = rep[id];
  return r;
}

} // namespace hoct
