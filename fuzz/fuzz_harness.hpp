// What a reader fuzz target does with one input, shared by the libFuzzer targets (fuzz/*.cpp)
// and the regression test that replays the inputs they found (tests/unit/test_fuzz_regressions):
// read it from memory, run the mesh checks and build_mesh, and for small meshes (<= 64 cells,
// degree <= 5) compute the exact contour tree and check its basic invariants. hoct::Error is an
// acceptable outcome at every step; a broken tree is returned as a description, any other
// exception propagates (both are findings, as are crashes and sanitizer reports).
#pragma once

#include "exact/exact_contour_tree.hpp"
#include "io/msh_reader.hpp"
#include "io/pos_reader.hpp"
#include "io/vtu_reader.hpp"
#include "mesh/mesh.hpp"
#include "tree/union_find.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace hoct::fuzz {

enum class Target { Vtu, Msh41Ascii, Msh41Binary, Msh22, Pos };

constexpr std::size_t kMaxTreeCells = 64;
constexpr int kMaxTreeDegree = 5;
// The budget the targets read with (the fuzzer's RSS limit is 2 GiB).
constexpr uint64_t kMemoryBudget = uint64_t{1} << 30;

// An MSH target reads inputs that do not start with "$MeshFormat" as the body of a file of its
// format, so that mutations of the sections are read as that format.
inline std::string msh_input(Target target, std::string bytes) {
  if (bytes.rfind("$MeshFormat", 0) == 0)
    return bytes;
  if (target == Target::Msh41Ascii)
    return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + bytes;
  if (target == Target::Msh22)
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + bytes;
  const char one[4] = {1, 0, 0, 0}; // little-endian int 1
  return "$MeshFormat\n4.1 1 8\n" + std::string(one, 4) + "\n$EndMeshFormat\n" + bytes;
}

// Empty if the tree has nodes - 1 arcs, each between two distinct nodes with the lower one
// (index and value) first, is connected, and sum over the nodes of (degree - 2) = -2. With
// tree = false (a domain that is not a disk or a sphere, whose level-set graph is no tree: the CLI
// refuses it, see apps/hoct/domain_check.hpp), only the arcs are checked.
inline std::string tree_invariant_violation(const TreeResult &t, bool tree = true) {
  const auto n = static_cast<int64_t>(t.nodes.size());
  if (n == 0)
    return "empty tree";
  if (tree && static_cast<int64_t>(t.arcs.size()) != n - 1)
    return "arcs != nodes - 1";
  std::vector<int64_t> degree(static_cast<std::size_t>(n), 0);
  UnionFind uf(static_cast<std::size_t>(n));
  for (const auto &a : t.arcs) {
    if (a[0] < 0 || a[1] < 0 || a[0] >= n || a[1] >= n)
      return "arc index out of range";
    if (a[0] >= a[1])
      return "arc not from the lower to the higher node";
    if (!(t.nodes[a[0]].value <= t.nodes[a[1]].value))
      return "arc descends in value (or a value is NaN)";
    ++degree[a[0]];
    ++degree[a[1]];
    uf.unite(a[0], a[1]);
  }
  if (!tree)
    return {};
  int64_t sum = 0;
  for (int64_t i = 0; i < n; ++i) {
    sum += degree[i] - 2;
    if (uf.find(i) != uf.find(0))
      return "tree not connected";
  }
  if (sum != -2)
    return "sum(deg - 2) != -2";
  return {};
}

// Runs one input through the target's pipeline; returns a description of a finding or "".
inline std::string run_one(Target target, std::string bytes) {
  MeshInput input;
  const ReadLimits limits{.max_memory_bytes = kMemoryBudget};
  Mesh mesh;
  try {
    if (target == Target::Vtu)
      input = read_vtu_buffer(std::move(bytes), "fuzz.vtu", "", limits);
    else if (target == Target::Pos)
      input = read_pos_buffer(std::move(bytes), "fuzz.pos", "", limits);
    else
      input = read_msh_buffer(msh_input(target, std::move(bytes)), "fuzz.msh", "", limits);
    mesh = build_mesh(input);
  } catch (const Error &) {
    return {};
  }
  if (input.num_cells() == 0 || input.num_cells() > kMaxTreeCells ||
      *std::max_element(input.cell_degree.begin(), input.cell_degree.end()) > kMaxTreeDegree)
    return {};
  const Topology &top = mesh.topology;
  const bool simply_connected =
      top.components() == 1 && ((top.euler_characteristic() == 1 && top.boundary_loops() == 1) ||
                                (top.euler_characteristic() == 2 && top.boundary_loops() == 0));
  try {
    return tree_invariant_violation(exact_contour_tree(mesh), simply_connected);
  } catch (const Error &) {
    return {};
  }
}

} // namespace hoct::fuzz
