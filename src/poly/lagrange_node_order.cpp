#include "poly/lagrange_node_order.hpp"

#include "poly/lattice.hpp"

#include <array>
#include <map>
#include <mutex>
#include <stdexcept>

namespace hoct {
namespace {

// Appends, in recursive corner/edge/interior order, the lattice points (a, b) of the sub-triangle
// of degree n whose corner 0 is at (a0, b0) in a degree-d lattice. The sub-triangle's corners are
// (a0, b0), (a0 + n, b0), (a0, b0 + n).
void recursive_order(int d, int a0, int b0, int n, std::vector<int> &out) {
  if (n < 0)
    return;
  if (n == 0) {
    out.push_back(lattice_index(d, a0, b0));
    return;
  }
  const std::array<std::array<int, 2>, 3> corner = {{{a0, b0}, {a0 + n, b0}, {a0, b0 + n}}};
  for (const auto &c : corner)
    out.push_back(lattice_index(d, c[0], c[1]));
  for (int e = 0; e < 3; ++e) {
    const auto &p = corner[e];
    const auto &q = corner[(e + 1) % 3];
    for (int t = 1; t < n; ++t) {
      const int a = p[0] + (q[0] - p[0]) * t / n;
      const int b = p[1] + (q[1] - p[1]) * t / n;
      out.push_back(lattice_index(d, a, b));
    }
  }
  recursive_order(d, a0 + 1, b0 + 1, n - 3, out);
}

// Appends, Gmsh's recursive way, the tensor indices of the sub-quadrangle of order n whose corner
// (0,0) is at (i0, i0) in a grid of order p.
void gmsh_quad_order(int p, int i0, int n, std::vector<int> &out) {
  auto index = [p](int i, int j) { return i + (p + 1) * j; };
  if (n < 0)
    return;
  if (n == 0) {
    out.push_back(index(i0, i0));
    return;
  }
  const std::array<std::array<int, 2>, 4> corner = {
      {{i0, i0}, {i0 + n, i0}, {i0 + n, i0 + n}, {i0, i0 + n}}};
  for (const auto &c : corner)
    out.push_back(index(c[0], c[1]));
  for (int e = 0; e < 4; ++e) {
    const auto &a = corner[e];
    const auto &b = corner[(e + 1) % 4];
    for (int t = 1; t < n; ++t)
      out.push_back(index(a[0] + (b[0] - a[0]) * t / n, a[1] + (b[1] - a[1]) * t / n));
  }
  gmsh_quad_order(p, i0 + 1, n - 2, out);
}

// VTK's order (vtkHigherOrderQuadrilateral's point numbering).
void vtk_quad_order(int p, std::vector<int> &out) {
  auto index = [p](int i, int j) { return i + (p + 1) * j; };
  out.push_back(index(0, 0));
  out.push_back(index(p, 0));
  out.push_back(index(p, p));
  out.push_back(index(0, p));
  for (int i = 1; i < p; ++i)
    out.push_back(index(i, 0));
  for (int j = 1; j < p; ++j)
    out.push_back(index(p, j));
  for (int i = 1; i < p; ++i)
    out.push_back(index(i, p));
  for (int j = 1; j < p; ++j)
    out.push_back(index(0, j));
  for (int j = 1; j < p; ++j)
    for (int i = 1; i < p; ++i)
      out.push_back(index(i, j));
}

template <class Make>
const std::vector<int> &cached(int kind, NodeOrdering ordering, int degree, Make make) {
  static std::mutex mutex;
  static std::map<std::array<int, 3>, std::vector<int>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  const std::array<int, 3> key{kind, static_cast<int>(ordering), degree};
  auto it = cache.find(key);
  if (it != cache.end())
    return it->second;
  return cache.emplace(key, make()).first->second;
}

} // namespace

const std::vector<int> &quad_node_order_to_tensor(NodeOrdering ordering, int p) {
  if (p < 1 || p > 64)
    throw std::invalid_argument("quad_node_order_to_tensor: unsupported degree " +
                                std::to_string(p));
  return cached(1, ordering, p, [&] {
    std::vector<int> perm;
    if (ordering == NodeOrdering::Vtk)
      vtk_quad_order(p, perm);
    else
      gmsh_quad_order(p, 0, p, perm);
    return perm;
  });
}

const std::vector<int> &serendipity_node_order(NodeOrdering ordering, int p) {
  if (p < 2 || p > 64)
    throw std::invalid_argument("serendipity_node_order: unsupported degree " + std::to_string(p));
  return cached(2, ordering, p, [&] {
    // The complete order's first 4p positions are the boundary nodes, in the same order for both
    // tools' incomplete cells; canonical position = rank of the tensor index among the boundary.
    const std::vector<int> &full = quad_node_order_to_tensor(ordering, p);
    std::vector<int> rank((p + 1) * (p + 1), -1);
    int r = 0;
    for (int j = 0; j <= p; ++j)
      for (int i = 0; i <= p; ++i)
        if (i == 0 || j == 0 || i == p || j == p)
          rank[i + (p + 1) * j] = r++;
    std::vector<int> perm;
    for (int b = 0; b < 4 * p; ++b)
      perm.push_back(rank[full[b]]);
    return perm;
  });
}

const std::vector<int> &node_order_to_lattice(NodeOrdering ordering, int degree) {
  if (degree < 1 || degree > 64)
    throw std::invalid_argument("node_order_to_lattice: unsupported degree " +
                                std::to_string(degree));
  static std::mutex mutex;
  static std::map<std::pair<int, int>, std::vector<int>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto key = std::make_pair(static_cast<int>(ordering), degree);
  auto it = cache.find(key);
  if (it != cache.end())
    return it->second;
  std::vector<int> perm;
  perm.reserve(lattice_size(degree));
  // VTK and Gmsh agree on the recursive ordering for complete triangles.
  recursive_order(degree, 0, 0, degree, perm);
  return cache.emplace(key, std::move(perm)).first->second;
}

int degree_from_node_count(long long n) {
  for (int d = 1; d <= 64; ++d)
    if (lattice_size(d) == n)
      return d;
  return -1;
}

} // namespace hoct
