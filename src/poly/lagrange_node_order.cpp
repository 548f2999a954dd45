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

} // namespace

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
