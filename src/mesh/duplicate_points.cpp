#include "mesh/duplicate_points.hpp"

#include "util/concurrent_sets.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"
#include "util/parallel_sort.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace hoct {

std::array<Vec3, 2> bounding_box(std::span<const Vec3> points, int threads) {
  if (points.empty())
    return {Vec3{0, 0, 0}, Vec3{0, 0, 0}};
  const int64_t n = static_cast<int64_t>(points.size());
  const int workers = threads_for(n, threads, 1 << 20);
  std::vector<std::array<Vec3, 2>> boxes(static_cast<std::size_t>(workers), {points[0], points[0]});
  parallel_for(n, workers, [&](int64_t begin, int64_t end, int worker) {
    Vec3 lo = points[begin], hi = lo;
    for (int64_t p = begin; p < end; ++p)
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], points[p][i]);
        hi[i] = std::max(hi[i], points[p][i]);
      }
    auto &box = boxes[static_cast<std::size_t>(worker)];
    for (int i = 0; i < 3; ++i) {
      box[0][i] = std::min(box[0][i], lo[i]);
      box[1][i] = std::max(box[1][i], hi[i]);
    }
  });
  std::array<Vec3, 2> box = boxes[0];
  for (const auto &b : boxes)
    for (int i = 0; i < 3; ++i) {
      box[0][i] = std::min(box[0][i], b[0][i]);
      box[1][i] = std::max(box[1][i], b[1][i]);
    }
  return box;
}

double bounding_box_diagonal(std::span<const Vec3> points, int threads) {
  if (points.empty())
    return 0;
  const auto [lo, hi] = bounding_box(points, threads);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

namespace {

using Key = std::array<int64_t, 3>;

// Grid cell of p for cells of size h from the corner lo (saturating far away).
Key grid_key(const Vec3 &p, const Vec3 &lo, double h) {
  Key k;
  for (int i = 0; i < 3; ++i) {
    const double q = std::floor((p[i] - lo[i]) / h);
    k[i] = q < 4e18 ? static_cast<int64_t>(q) : int64_t{4000000000000000000};
  }
  return k;
}

// Points in at most this many per coarse cell are compared pairwise.
constexpr std::size_t kPairwiseLimit = 64;

} // namespace

std::vector<int64_t> coincident_points(std::span<const Vec3> points,
                                       const std::vector<int64_t> &candidates, double tolerance,
                                       int threads) {
  const std::size_t n = candidates.size();
  std::vector<int64_t> result(candidates.begin(), candidates.end());
  if (n < 2 || !(tolerance > 0) || !std::isfinite(tolerance))
    return result;
  Vec3 lo = points[candidates[0]], hi = lo;
  for (int64_t c : candidates)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], points[c][i]);
      hi[i] = std::max(hi[i], points[c][i]);
    }
  // An axis along which every point has the same coordinate (z of a planar mesh) has no
  // neighbouring cells to look in: no point is "near a face" across it.
  const bool spread[3] = {hi[0] > lo[0], hi[1] > lo[1], hi[2] > lo[2]};
  ConcurrentSets uf(static_cast<int64_t>(n), threads);
  const double tol2 = tolerance * tolerance;
  auto close = [&](std::size_t i, std::size_t j) {
    const Vec3 &p = points[candidates[i]], &q = points[candidates[j]];
    const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                      (p[2] - q[2]) * (p[2] - q[2]);
    return d2 <= tol2;
  };
  // Coarse cells of 1024 tolerances: points closer than the tolerance share a coarse cell unless
  // one of them lies within the tolerance of a cell face (a few in a thousand), and meshes rarely
  // put two vertices in one coarse cell. Pairs within a cell are compared directly; points near
  // a face also against the neighbouring cells; crowded cells (many vertices within 1e-7 of the
  // diagonal) by a fine grid of cells of one tolerance and its 27 neighbours.
  const double h = 1024 * tolerance;
  // Each point's coarse cell, and the faces of it the point lies within the tolerance of (bit
  // 2 ax: the lower face along axis ax, bit 2 ax + 1: the upper one), both found in one pass over
  // the points in candidate order.
  PooledVector<std::pair<Key, std::size_t>> sorted(n);
  UninitializedVector<uint8_t> faces(n);
  const int64_t count = static_cast<int64_t>(n);
  parallel_for(count, threads_for(count, threads, 65536), [&](int64_t begin, int64_t end, int) {
    for (int64_t i = begin; i < end; ++i) {
      const Vec3 &p = points[candidates[i]];
      const Key key = grid_key(p, lo, h);
      sorted[i] = {key, static_cast<std::size_t>(i)};
      uint8_t near = 0;
      for (int ax = 0; ax < 3; ++ax) {
        if (!spread[ax])
          continue;
        const double x = p[ax] - lo[ax];
        // Within two tolerances (a margin for the rounding of the keys).
        if (x - 2 * tolerance < static_cast<double>(key[ax]) * h)
          near |= static_cast<uint8_t>(1u << (2 * ax));
        if (x + 2 * tolerance >= static_cast<double>(key[ax] + 1) * h)
          near |= static_cast<uint8_t>(2u << (2 * ax));
      }
      faces[i] = near;
    }
  });
  // (key, index) pairs are distinct: the same order on any thread count. The pairs' own order,
  // compared field by field (std::pair's operator< goes through std::array's lexicographical
  // comparison, which the compiler does not reduce to these few compares).
  parallel_sort(sorted.begin(), sorted.end(), threads,
                [](const std::pair<Key, std::size_t> &a, const std::pair<Key, std::size_t> &b) {
                  if (a.first[0] != b.first[0])
                    return a.first[0] < b.first[0];
                  if (a.first[1] != b.first[1])
                    return a.first[1] < b.first[1];
                  if (a.first[2] != b.first[2])
                    return a.first[2] < b.first[2];
                  return a.second < b.second;
                });

  // Crowded cells keep their fine-grid order for the lookups from neighbouring cells.
  std::vector<std::vector<std::pair<Key, std::size_t>>> crowded;
  std::vector<std::pair<std::size_t, std::size_t>> crowded_at; // (run start, index in crowded)
  auto search_fine = [&](const std::vector<std::pair<Key, std::size_t>> &fine, std::size_t i) {
    const Key key = grid_key(points[candidates[i]], lo, tolerance);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Key k = {key[0] + dx, key[1] + dy, key[2] + dz};
          for (auto it =
                   std::lower_bound(fine.begin(), fine.end(), std::make_pair(k, std::size_t{0}));
               it != fine.end() && it->first == k; ++it)
            if (it->second != i && close(i, it->second))
              uf.unite(static_cast<int64_t>(i), static_cast<int64_t>(it->second));
        }
  };
  for (std::size_t a = 0; a < n;) {
    std::size_t b = a + 1;
    while (b < n && sorted[b].first == sorted[a].first)
      ++b;
    if (b - a <= kPairwiseLimit) {
      for (std::size_t s = a; s < b; ++s)
        for (std::size_t t = s + 1; t < b; ++t)
          if (close(sorted[s].second, sorted[t].second))
            uf.unite(static_cast<int64_t>(sorted[s].second),
                     static_cast<int64_t>(sorted[t].second));
    } else {
      auto &fine = crowded.emplace_back();
      for (std::size_t s = a; s < b; ++s)
        fine.push_back(
            {grid_key(points[candidates[sorted[s].second]], lo, tolerance), sorted[s].second});
      std::sort(fine.begin(), fine.end());
      crowded_at.emplace_back(a, crowded.size() - 1);
      for (const auto &entry : fine)
        search_fine(fine, entry.second);
    }
    a = b;
  }
  // Points within the tolerance of a face of their coarse cell: against the neighbouring cells,
  // in key order (consecutive lookups share their search paths), on threads (unions commute).
  parallel_for(count, threads_for(count, threads, 65536), [&](int64_t begin, int64_t end, int) {
    for (int64_t at = begin; at < end; ++at) {
      const auto &[key, i] = sorted[static_cast<std::size_t>(at)];
      const unsigned f = faces[i];
      if (f == 0)
        continue;
      int lo_side[3], hi_side[3];
      for (int ax = 0; ax < 3; ++ax) {
        lo_side[ax] = (f >> (2 * ax)) & 1u ? -1 : 0;
        hi_side[ax] = (f >> (2 * ax + 1)) & 1u ? 1 : 0;
      }
      for (int dx = lo_side[0]; dx <= hi_side[0]; ++dx)
        for (int dy = lo_side[1]; dy <= hi_side[1]; ++dy)
          for (int dz = lo_side[2]; dz <= hi_side[2]; ++dz) {
            if (dx == 0 && dy == 0 && dz == 0)
              continue;
            const Key k = {key[0] + dx, key[1] + dy, key[2] + dz};
            const auto b =
                std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(k, std::size_t{0}));
            if (b == sorted.end() || b->first != k)
              continue;
            const std::size_t start = static_cast<std::size_t>(b - sorted.begin());
            const auto c = std::lower_bound(crowded_at.begin(), crowded_at.end(),
                                            std::make_pair(start, std::size_t{0}));
            if (c != crowded_at.end() && c->first == start) {
              search_fine(crowded[c->second], i);
              continue;
            }
            for (auto it = b; it != sorted.end() && it->first == k; ++it)
              if (close(i, it->second))
                uf.unite(static_cast<int64_t>(i), static_cast<int64_t>(it->second));
          }
    }
  });
  // Each group's root is its first candidate: with ascending candidates (the mesh's vertices,
  // every point) also its smallest id; otherwise the smallest is looked for.
  UninitializedVector<int64_t> root(n);
  parallel_for(count, threads_for(count, threads, 65536), [&](int64_t begin, int64_t end, int) {
    for (int64_t i = begin; i < end; ++i)
      root[i] = uf.find(i);
  });
  if (std::is_sorted(candidates.begin(), candidates.end())) {
    for (std::size_t i = 0; i < n; ++i)
      result[i] = candidates[root[i]];
    return result;
  }
  std::vector<int64_t> smallest(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    int64_t &m = smallest[root[i]];
    if (m < 0 || candidates[i] < m)
      m = candidates[i];
  }
  for (std::size_t i = 0; i < n; ++i)
    result[i] = smallest[root[i]];
  return result;
}

MergeReport merge_duplicate_points(MeshInput &input, double relative_tolerance, int threads) {
  MergeReport r;
  const std::size_t np = input.points.size();
  std::vector<int64_t> all(np);
  for (std::size_t i = 0; i < np; ++i)
    all[i] = static_cast<int64_t>(i);
  const double tol = relative_tolerance * bounding_box_diagonal(input.points, threads);
  const std::vector<int64_t> rep = coincident_points(input.points, all, tol, threads);
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
