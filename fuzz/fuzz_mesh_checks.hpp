// What every reader fuzz target does with a mesh it read: the mesh checks and build_mesh, and for
// small inputs the exact contour tree, whose basic invariants are asserted. hoct::Error is an
// acceptable outcome at every step; anything else (another exception, a crash, a sanitizer
// report, a broken tree) is a finding.
#pragma once

#include "error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_input.hpp"
#include "tree/exact_contour_tree.hpp"
#include "tree/union_find.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace hoct::fuzz {

// Inputs small enough for the exact tree in a fuzzing iteration.
constexpr std::size_t kMaxTreeCells = 64;
constexpr int kMaxTreeDegree = 5;

[[noreturn]] inline void finding(const char *what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what);
  std::abort();
}

// nodes - 1 arcs, every arc between two distinct nodes with the lower one first, connected, and
// sum over the nodes of (degree - 2) = -2.
inline void check_tree_invariants(const TreeResult &t) {
  const auto n = static_cast<int64_t>(t.nodes.size());
  if (n == 0)
    finding("empty tree");
  if (static_cast<int64_t>(t.arcs.size()) != n - 1)
    finding("arcs != nodes - 1");
  std::vector<int64_t> degree(static_cast<std::size_t>(n), 0);
  UnionFind uf(static_cast<std::size_t>(n));
  for (const auto &a : t.arcs) {
    if (a[0] < 0 || a[1] < 0 || a[0] >= n || a[1] >= n)
      finding("arc index out of range");
    if (a[0] >= a[1])
      finding("arc not from the lower to the higher node");
    if (t.nodes[a[0]].value > t.nodes[a[1]].value)
      finding("arc descends in value");
    ++degree[a[0]];
    ++degree[a[1]];
    uf.unite(a[0], a[1]);
  }
  int64_t sum = 0;
  for (int64_t i = 0; i < n; ++i) {
    sum += degree[i] - 2;
    if (uf.find(i) != uf.find(0))
      finding("tree not connected");
  }
  if (sum != -2)
    finding("sum(deg - 2) != -2");
}

inline void check_mesh_input(const MeshInput &input) {
  Mesh mesh;
  try {
    mesh = build_mesh(input);
  } catch (const Error &) {
    return;
  }
  if (input.num_cells() == 0 || input.num_cells() > kMaxTreeCells)
    return;
  if (*std::max_element(input.cell_degree.begin(), input.cell_degree.end()) > kMaxTreeDegree)
    return;
  try {
    check_tree_invariants(exact_contour_tree(mesh));
  } catch (const Error &) {
  }
}

} // namespace hoct::fuzz
