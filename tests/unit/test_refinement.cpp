// Exact refinement: conforming (the refined mesh has the same topology), values from the exact
// field, no degenerate or inverted sub-triangles, with and without extra edge points.
#include "mesh/mesh.hpp"
#include "pl/refinement.hpp"
#include "test_meshes.hpp"

#include <gtest/gtest.h>

namespace hoct {
namespace {

Mesh sample_mesh(bool sphere, int degree, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  if (sphere)
    testing::octahedron(2, v, t);
  else
    testing::square_grid(3, rng, v, t);
  const MeshInput in = testing::lagrange_mesh(
      v, t, [&](int64_t) { return degree; }, sphere ? testing::sphere_projection : nullptr,
      [](const Vec3 &p) { return std::sin(3 * p[0]) * std::cos(2 * p[1]) + p[2]; }, rng);
  return build_mesh(in);
}

void check_refinement(const Mesh &m, const PlMesh &pl, int64_t euler, int64_t loops) {
  const Mesh r = build_mesh(to_mesh_input(pl), {.throw_on_error = false});
  EXPECT_FALSE(r.problems.has_errors()) << r.problems.summary();
  EXPECT_EQ(r.topology.euler_characteristic(), euler);
  EXPECT_EQ(r.topology.boundary_loops(), loops);
  EXPECT_EQ(r.topology.components(), 1);
  // Every sub-vertex is a corner of some sub-triangle (none dropped).
  EXPECT_EQ(r.topology.num_vertices(), pl.num_vertices());
  for (int64_t i = 0; i < pl.num_vertices(); ++i) {
    const int64_t c = pl.source_cell[i];
    ASSERT_GE(c, 0);
    const auto uv = pl.source_uv[i];
    EXPECT_NEAR(pl.values[i], m.field.value(c, uv[0], uv[1]), 1e-12);
    const Vec3 p = m.geometry.position(c, uv[0], uv[1]);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(pl.points[i][a], p[a], 1e-12);
  }
}

TEST(Refinement, UniformIsConformingAndExact) {
  for (bool sphere : {false, true})
    for (int d : {1, 2, 3, 5})
      for (int k : {1, 2, 4}) {
        const Mesh m = sample_mesh(sphere, d, 10 + d);
        const PlMesh pl = refine(m, k);
        EXPECT_EQ(static_cast<int64_t>(pl.triangles.size()), m.topology.num_cells() * k * k);
        check_refinement(m, pl, sphere ? 2 : 1, sphere ? 0 : 1);
      }
}

TEST(Refinement, ExtraEdgePointsAreSharedSubVertices) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0.01, 0.99);
  for (bool sphere : {false, true})
    for (int k : {1, 2, 3}) {
      const Mesh m = sample_mesh(sphere, 3, 20 + k);
      RefinementOptions opt;
      opt.k = k;
      opt.edge_points.resize(m.topology.num_edges());
      int64_t added = 0;
      for (auto &pts : opt.edge_points)
        for (int i = 0, n = static_cast<int>(rng() % 3); i < n; ++i, ++added)
          pts.push_back(U(rng));
      const PlMesh plain = refine(m, k);
      const PlMesh pl = refine(m, opt);
      EXPECT_GE(pl.num_vertices(), plain.num_vertices() + added);
      check_refinement(m, pl, sphere ? 2 : 1, sphere ? 0 : 1);
    }
}

} // namespace
} // namespace hoct
