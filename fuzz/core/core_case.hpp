// The core fuzz target's decoding, shared by fuzz/core/fuzz_core.cpp (libFuzzer) and the
// regression test that replays kept inputs (tests/unit/test_fuzz_core_regressions.cpp): bytes ->
// a small Lagrange triangle mesh (1-16 cells of a 3 x 3 grid with jittered vertices, degree 1-5
// per cell) and node values (raw doubles, small integers for ties and plateaus, and NaN, inf,
// huge, tiny and repeated values to provoke degeneracies) -> the exact contour tree, which must
// pass the invariant checker unless a hoct::Error explains why there is none.
#pragma once

#include "../../tests/unit/test_meshes.hpp"
#include "analysis/tree_check.hpp"
#include "exact/exact_contour_tree.hpp"
#include "mesh/mesh.hpp"
#include "util/error.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

namespace hoct::fuzzing {

class ByteReader {
public:
  ByteReader(const uint8_t *data, std::size_t size) : d_(data), n_(size) {}
  uint8_t byte() { return pos_ < n_ ? d_[pos_++] : 0; }
  double raw_double() {
    uint8_t b[8];
    for (auto &x : b)
      x = byte();
    double v;
    std::memcpy(&v, b, 8);
    return v;
  }

private:
  const uint8_t *d_;
  std::size_t n_, pos_ = 0;
};

// A node value: mostly small integers (ties, plateaus) and moderate decimals, sometimes special.
inline double decode_value(ByteReader &in, double previous) {
  const uint8_t mode = in.byte();
  switch (mode % 16) {
  case 0:
    return std::numeric_limits<double>::quiet_NaN();
  case 1:
    return (mode & 16) ? std::numeric_limits<double>::infinity()
                       : -std::numeric_limits<double>::infinity();
  case 2:
    return (mode & 16 ? -1 : 1) * ((mode & 32) ? 1e300 : std::numeric_limits<double>::max() / 4);
  case 3:
    return (mode & 16 ? -1 : 1) *
           ((mode & 32) ? 1e-300 : std::numeric_limits<double>::denorm_min());
  case 4:
  case 5:
    return previous; // ties
  case 6:
    return in.raw_double();
  case 7:
  case 8:
  case 9:
    return static_cast<double>(static_cast<int8_t>(in.byte())) / 16;
  default:
    return static_cast<double>(static_cast<int>(in.byte() % 7) - 3);
  }
}

// The mesh input described by the bytes.
inline MeshInput decode_input(ByteReader &in) {
  const int ncells = 1 + in.byte() % 16;
  // Vertices of a 3 x 3 grid of squares on [0, 3]^2, each jittered by up to 0.45 per axis.
  std::vector<Vec3> verts;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) {
      const double dx = (static_cast<int>(in.byte()) - 128) / 128.0 * 0.45;
      const double dy = (static_cast<int>(in.byte()) - 128) / 128.0 * 0.45;
      verts.push_back({i + dx, j + dy, 0.0});
    }
  std::vector<std::array<int64_t, 3>> tris;
  auto id = [](int i, int j) { return static_cast<int64_t>(j * 4 + i); };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const bool flip = in.byte() & 1; // which diagonal
      if (flip) {
        tris.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        tris.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  tris.resize(ncells);
  // Only the vertices the cells use (an unused point's value would still be checked).
  std::vector<int64_t> remap(verts.size(), -1);
  std::vector<Vec3> used;
  for (auto &t : tris)
    for (auto &v : t) {
      if (remap[v] < 0) {
        remap[v] = static_cast<int64_t>(used.size());
        used.push_back(verts[v]);
      }
      v = remap[v];
    }
  std::vector<int> degree(ncells);
  for (int &d : degree)
    d = 1 + in.byte() % 5;
  std::mt19937_64 rng(in.byte());
  double previous = 0;
  return testing::lagrange_mesh(
      used, tris, [&](int64_t c) { return degree[c]; }, {},
      [&](const Vec3 &) { return previous = decode_value(in, previous); }, rng);
}

// Options byte bits 2-4: squash the mesh along y by 10^-(1 + bits 3-4) (slivers of aspect ratio
// up to ~10^4, searched in their own shape by find_gradient_zeros).
inline void apply_squash(MeshInput &input, uint8_t options) {
  if (!(options & 4))
    return;
  const double factor = std::pow(10.0, -(1 + ((options >> 3) & 3)));
  for (Vec3 &p : input.points)
    p[1] *= factor;
}

// Builds the mesh described by the bytes (throws hoct::Error for an invalid one).
inline Mesh decode_mesh(ByteReader &in) { return build_mesh(decode_input(in)); }

inline Mesh decode_mesh(const uint8_t *data, std::size_t size) {
  ByteReader in(data, size);
  return decode_mesh(in);
}

// The same nodes (type, value, position, cell, uv) and arcs.
inline bool same_tree(const TreeResult &a, const TreeResult &b) {
  if (a.nodes.size() != b.nodes.size() || a.arcs != b.arcs)
    return false;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const TreeNode &x = a.nodes[i], &y = b.nodes[i];
    if (x.type != y.type || x.value != y.value || x.position != y.position || x.cell != y.cell ||
        x.uv != y.uv || x.merged != y.merged)
      return false;
  }
  return true;
}

// Runs the case. Returns an empty string if the tree passed the checker or the input was
// refused with hoct::Error; else the findings. A byte after the mesh (absent: 0) asks for the
// augmented tree (bit 0), for a second computation on 3 threads that must be identical (bit 1)
// and squashes the mesh into slivers (bits 2-4, apply_squash).
inline std::string run_core_case(const uint8_t *data, std::size_t size) {
  try {
    ByteReader in(data, size);
    MeshInput input = decode_input(in);
    const uint8_t options = in.byte();
    apply_squash(input, options);
    const Mesh mesh = build_mesh(input);
    ExactTreeOptions o;
    o.threads = 1;
    o.augmented = options & 1;
    auto compute = [&] {
      const TreeResult t = exact_contour_tree(mesh, o);
      return o.augmented ? t : contract_flat(t);
    };
    const TreeResult tree = compute();
    const TreeCheckReport r = check_tree(tree, mesh);
    if (!r.ok())
      return r.summary();
    if (options & 2) {
      o.threads = 3;
      if (!same_tree(tree, compute()))
        return "the tree on 3 threads differs from the tree on 1 thread\n";
    }
  } catch (const Error &) {
  }
  return "";
}

} // namespace hoct::fuzzing
