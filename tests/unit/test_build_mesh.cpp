// build_mesh on an input it consumes (MeshInput &&, as the CLI builds its meshes) gives the
// mesh and the report of build_mesh on a kept input, bit for bit, and leaves the input empty.
#include "mesh/mesh.hpp"
#include "test_meshes.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <random>
#include <span>

namespace hoct {
namespace {

MeshInput grid_mesh(uint64_t seed, int degree) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(24, rng, verts, tris);
  return testing::lagrange_mesh(
      verts, tris, [&](int64_t) { return degree; }, nullptr, nullptr, rng);
}

// The same doubles, bit for bit.
::testing::AssertionResult same_bits(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size())
    return ::testing::AssertionFailure() << a.size() << " and " << b.size() << " values";
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(double)) != 0)
      return ::testing::AssertionFailure() << "value " << i << ": " << a[i] << " and " << b[i];
  return ::testing::AssertionSuccess();
}

void expect_same(const Mesh &a, const Mesh &b) {
  ASSERT_EQ(a.complete, b.complete);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.field_name, b.field_name);
  EXPECT_EQ(a.num_points, b.num_points);
  EXPECT_EQ(a.problems.summary(), b.problems.summary());
  if (!a.complete)
    return;
  ASSERT_EQ(a.topology.num_vertices(), b.topology.num_vertices());
  ASSERT_EQ(a.topology.num_edges(), b.topology.num_edges());
  ASSERT_EQ(a.topology.num_cells(), b.topology.num_cells());
  for (int64_t e = 0; e < a.topology.num_edges(); ++e) {
    ASSERT_EQ(a.topology.edge_vertices(e), b.topology.edge_vertices(e));
    ASSERT_TRUE(same_bits(a.field.edge_coefficients(e), b.field.edge_coefficients(e)))
        << "edge " << e;
  }
  for (int64_t c = 0; c < a.topology.num_cells(); ++c) {
    ASSERT_EQ(a.topology.cell_vertices(c), b.topology.cell_vertices(c));
    ASSERT_TRUE(same_bits(a.field.coefficients(c), b.field.coefficients(c))) << "cell " << c;
    for (const auto &uv : {Vec2{0.2, 0.3}, Vec2{1.0 / 3, 1.0 / 3}, Vec2{0.7, 0.1}})
      ASSERT_TRUE(
          same_bits(a.geometry.position(c, uv[0], uv[1]), b.geometry.position(c, uv[0], uv[1])))
          << "cell " << c;
  }
}

void expect_consumed(const MeshInput &in, const std::string &source) {
  EXPECT_TRUE(in.points.empty());
  EXPECT_TRUE(in.values.empty());
  EXPECT_TRUE(in.cell_nodes.empty());
  EXPECT_EQ(in.num_cells(), 0u);
  EXPECT_EQ(in.source, source); // kept for messages
}

TEST(BuildMesh, ConsumedInputGivesTheSameMesh) {
  for (int degree : {1, 3, 5}) {
    const MeshInput kept = grid_mesh(5, degree);
    MeshInput consumed = kept;
    const Mesh a = build_mesh(kept, {.threads = 2});
    const Mesh b = build_mesh(std::move(consumed), {.threads = 2});
    ASSERT_TRUE(a.complete);
    expect_same(a, b);
    expect_consumed(consumed, kept.source);
  }
}

TEST(BuildMesh, ConsumedInputGivesTheSameReport) {
  // Defects each check reports: a duplicated vertex (duplicate check), a discontinuous edge
  // (field), a folded cell (geometry).
  MeshInput bad = grid_mesh(6, 3);
  bad.points.push_back(bad.points[bad.cell_nodes[0]]);
  bad.values.push_back(bad.values[bad.cell_nodes[0]]);
  bad.cell_nodes[bad.cell_offsets[7]] = static_cast<int64_t>(bad.points.size() - 1);
  // Cell 40's first edge node, shared with its neighbour, replaced by a copy of its own with
  // another value: the field jumps across that edge.
  int64_t &edge_node = bad.cell_nodes[bad.cell_offsets[40] + edge_lattice_index(3, 0, 1)];
  bad.points.push_back(bad.points[edge_node]);
  bad.values.push_back(bad.values[edge_node] + 0.5);
  edge_node = static_cast<int64_t>(bad.points.size() - 1);
  std::swap(bad.points[bad.cell_nodes[bad.cell_offsets[90]]],
            bad.points[bad.cell_nodes[bad.cell_offsets[90] + 1]]);
  const MeshBuildOptions keep_going{.throw_on_error = false};
  MeshInput consumed = bad;
  const Mesh a = build_mesh(bad, keep_going);
  const Mesh b = build_mesh(std::move(consumed), keep_going);
  for (const char *kind : {"duplicate vertices", "disagree on their shared edge", "inverted cell"})
    EXPECT_NE(a.problems.summary().find(kind), std::string::npos) << kind;
  expect_same(a, b);
  expect_consumed(consumed, bad.source);
  // Thrown: the same message, naming the source.
  std::string kept_message, consumed_message;
  try {
    build_mesh(bad);
  } catch (const Error &e) {
    kept_message = e.what();
  }
  try {
    build_mesh(MeshInput(bad));
  } catch (const Error &e) {
    consumed_message = e.what();
  }
  EXPECT_FALSE(kept_message.empty());
  EXPECT_EQ(kept_message, consumed_message);
  EXPECT_NE(consumed_message.find(bad.source), std::string::npos);
}

// The build's steps are timed one after the other: each time is set, and they add up to no more
// than the build's wall time.
TEST(BuildMesh, TimesEachStep) {
  const MeshInput input = grid_mesh(7, 3);
  const auto start = std::chrono::steady_clock::now();
  const Mesh m = build_mesh(input, {.threads = 2});
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const MeshBuildTimes &t = m.build_times;
  for (double s :
       {t.input_checks, t.topology, t.duplicate_vertices, t.geometry, t.field, t.geometry_checks})
    EXPECT_GT(s, 0);
  EXPECT_LE(t.total(), wall);
  // An input refused by its first checks times those only.
  MeshInput broken = input;
  broken.cell_nodes[3] = -5;
  const Mesh b = build_mesh(broken, {.throw_on_error = false});
  EXPECT_FALSE(b.complete);
  EXPECT_GT(b.build_times.input_checks, 0);
  EXPECT_EQ(b.build_times.topology, 0);
  EXPECT_EQ(b.build_times.field, 0);
}

} // namespace
} // namespace hoct
