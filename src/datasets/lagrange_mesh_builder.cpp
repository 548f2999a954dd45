#include "datasets/lagrange_mesh_builder.hpp"

#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <array>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace hoct {
namespace {

// The edges of a linear mesh, found in linear time: half-edges bucketed by their lower vertex,
// each bucket (a handful of entries) sorted by the higher vertex.
struct EdgeTable {
  std::vector<std::array<int64_t, 2>> ends; // (lower, higher) vertex id per edge
  std::vector<int64_t> of_half_edge;        // edge id of half-edge 3 t + k (corner k -> k+1)
};

EdgeTable find_edges(const LinearMesh &mesh) {
  const int64_t nv = static_cast<int64_t>(mesh.vertices.size());
  const int64_t nt = static_cast<int64_t>(mesh.triangles.size());
  std::vector<int64_t> start(nv + 1, 0);
  for (const auto &t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (int64_t v = 0; v < nv; ++v)
    start[v + 1] += start[v];
  struct Entry {
    int64_t hi, half_edge;
  };
  std::vector<Entry> bucket(static_cast<std::size_t>(3 * nt));
  std::vector<int64_t> fill(start.begin(), start.end() - 1);
  for (int64_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int64_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      bucket[fill[std::min(a, b)]++] = {std::max(a, b), 3 * t + k};
    }
  EdgeTable table;
  table.of_half_edge.resize(static_cast<std::size_t>(3 * nt));
  table.ends.reserve(static_cast<std::size_t>(3 * nt / 2 + nv + 1));
  for (int64_t v = 0; v < nv; ++v) {
    auto first = bucket.begin() + start[v], last = bucket.begin() + start[v + 1];
    std::sort(first, last, [](const Entry &x, const Entry &y) {
      return x.hi != y.hi ? x.hi < y.hi : x.half_edge < y.half_edge;
    });
    for (auto it = first; it != last; ++it) {
      if (it == first || it->hi != (it - 1)->hi)
        table.ends.push_back({v, it->hi});
      table.of_half_edge[it->half_edge] = static_cast<int64_t>(table.ends.size() - 1);
    }
  }
  return table;
}

// Runs body(begin, end) over [0, n) in contiguous chunks on up to hardware_concurrency threads.
template <class Body> void parallel_ranges(int64_t n, const Body &body) {
  const int64_t min_chunk = 1 << 14;
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const int64_t threads =
      std::min<int64_t>(std::min<int64_t>(hw, 16), (n + min_chunk - 1) / min_chunk);
  if (threads <= 1) {
    body(int64_t{0}, n);
    return;
  }
  std::vector<std::thread> pool;
  std::exception_ptr failure;
  std::mutex failure_mutex;
  for (int64_t i = 0; i < threads; ++i)
    pool.emplace_back([&, i] {
      try {
        body(n * i / threads, n * (i + 1) / threads);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure)
          failure = std::current_exception();
      }
    });
  for (auto &t : pool)
    t.join();
  if (failure)
    std::rethrow_exception(failure);
}

Vec3 lerp3(const Vec3 &a, const Vec3 &b, const Vec3 &c, double wa, double wb, double wc) {
  return {wa * a[0] + wb * b[0] + wc * c[0], wa * a[1] + wb * b[1] + wc * c[1],
          wa * a[2] + wb * b[2] + wc * c[2]};
}

} // namespace

MeshInput build_lagrange_mesh(const LinearMesh &parent, int degree, const NodePlacement &place,
                              const NodeValue &value) {
  const int d = degree;
  if (d < 1 || d > 10)
    throw Error("lagrange mesh: degree must be between 1 and 10, got " + std::to_string(d));
  const int64_t nv = static_cast<int64_t>(parent.vertices.size());
  const int64_t nt = static_cast<int64_t>(parent.triangles.size());
  for (int64_t t = 0; t < nt; ++t) {
    const auto &tri = parent.triangles[t];
    for (int64_t id : tri)
      if (id < 0 || id >= nv)
        throw Error("lagrange mesh: triangle " + std::to_string(t) + " has corner id " +
                    std::to_string(id) + " out of range");
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
      throw Error("lagrange mesh: triangle " + std::to_string(t) + " repeats a corner");
  }

  const EdgeTable edges = find_edges(parent);
  const int64_t ne = static_cast<int64_t>(edges.ends.size());
  const int per_edge = d - 1, per_cell = (d - 1) * (d - 2) / 2;
  const int64_t edge_base = nv, cell_base = nv + ne * per_edge;
  const int64_t np = cell_base + nt * per_cell;

  // Interior lattice points of a cell, in canonical order.
  std::vector<std::array<int, 2>> interior;
  for (int b = 1; b < d; ++b)
    for (int a = 1; a + b < d; ++a)
      interior.push_back({a, b});

  MeshInput m;
  m.points.resize(static_cast<std::size_t>(np));
  m.values.resize(static_cast<std::size_t>(np));
  const double inv_d = 1.0 / d;
  auto flat_point = [&](int64_t id) -> Vec3 {
    if (id < edge_base)
      return parent.vertices[id];
    if (id < cell_base) {
      const int64_t e = (id - edge_base) / per_edge;
      const int s = static_cast<int>((id - edge_base) % per_edge) + 1;
      const Vec3 &a = parent.vertices[edges.ends[e][0]], &b = parent.vertices[edges.ends[e][1]];
      const double w = s * inv_d;
      return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])};
    }
    const int64_t t = (id - cell_base) / per_cell;
    const auto &ab = interior[(id - cell_base) % per_cell];
    const auto &tri = parent.triangles[t];
    const double u = ab[0] * inv_d, v = ab[1] * inv_d;
    return lerp3(parent.vertices[tri[0]], parent.vertices[tri[1]], parent.vertices[tri[2]],
                 1 - u - v, u, v);
  };
  parallel_ranges(np, [&](int64_t begin, int64_t end) {
    for (int64_t id = begin; id < end; ++id) {
      const Vec3 flat = flat_point(id);
      m.points[id] = place ? place(flat) : flat;
      m.values[id] = value(m.points[id], flat);
    }
  });

  const int L = lattice_size(d);
  m.cell_degree.assign(static_cast<std::size_t>(nt), static_cast<uint8_t>(d));
  m.cell_offsets.resize(static_cast<std::size_t>(nt + 1));
  m.cell_nodes.resize(static_cast<std::size_t>(nt * L));
  for (int64_t t = 0; t <= nt; ++t)
    m.cell_offsets[t] = t * L;
  parallel_ranges(nt, [&](int64_t begin, int64_t end) {
    for (int64_t t = begin; t < end; ++t) {
      int64_t *nodes = &m.cell_nodes[t * L];
      const auto &tri = parent.triangles[t];
      for (int k = 0; k < 3; ++k) {
        nodes[corner_index(d, k)] = tri[k];
        const int64_t e = edges.of_half_edge[3 * t + k];
        const bool forward = tri[k] == edges.ends[e][0];
        for (int s = 1; s < d; ++s)
          nodes[edge_lattice_index(d, k, s)] =
              edge_base + e * per_edge + (forward ? s - 1 : d - 1 - s);
      }
      for (int i = 0; i < per_cell; ++i)
        nodes[lattice_index(d, interior[i][0], interior[i][1])] = cell_base + t * per_cell + i;
    }
  });
  return m;
}

} // namespace hoct
