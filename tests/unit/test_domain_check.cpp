// pipeline/domain_check: a disk and a sphere are contour-tree domains, two components are named
// but pass (every method computes their Reeb graph), and a forceable problem is only forceable.
#include "datasets/datasets.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/domain_check.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>

namespace hoct {
namespace {

MeshInput two_triangles() {
  MeshInput two;
  two.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  two.values = {0, 1, 2, 3, 4, 5};
  two.source = "two.vtu";
  const int64_t a[3] = {0, 1, 2}, b[3] = {3, 4, 5};
  two.add_cell(1, a);
  two.add_cell(1, b);
  return two;
}

TEST(DomainCheck, DiskAndSphereAreTreesTwoComponentsPassNamed) {
  for (const char *name : {"two-triangle", "sphere"}) {
    const Mesh mesh = build_mesh(generate_dataset(name, {}));
    EXPECT_EQ(domain_shape(mesh.topology), "") << name;
    EXPECT_TRUE(check_domain(mesh, false).empty()) << name;
  }
  const Mesh two = build_mesh(two_triangles());
  EXPECT_NE(domain_shape(two.topology).find("2 separate components: 2 component(s)"),
            std::string::npos);
  EXPECT_TRUE(check_domain(two, false).empty());
  EXPECT_TRUE(check_domain(two, true).empty());
}

TEST(DomainCheck, OnlyForceableProblemsAreForced) {
  // An inverted cell (clockwise in a counter-clockwise disk) can be forced; a non-manifold edge
  // cannot.
  EXPECT_TRUE(problem_info(Problem::InvertedCell).forceable);
  EXPECT_TRUE(problem_info(Problem::FoldedCell).forceable);
  EXPECT_TRUE(problem_info(Problem::DuplicateVertices).forceable);
  EXPECT_FALSE(problem_info(Problem::NonManifoldEdge).forceable);
  EXPECT_FALSE(problem_info(Problem::NonFiniteValue).forceable);
  MeshInput fin;
  fin.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  fin.values = {0, 1, 2, 3, 4};
  fin.source = "fin";
  const int64_t a[3] = {0, 1, 2}, b[3] = {1, 0, 3}, c[3] = {0, 1, 4};
  fin.add_cell(1, a);
  fin.add_cell(1, b);
  fin.add_cell(1, c);
  const Mesh m = build_mesh(fin, {.throw_on_error = false});
  ASSERT_GT(m.problems.count(Problem::NonManifoldEdge), 0);
  for (bool force : {false, true})
    EXPECT_THROW(check_domain(m, force), Error) << force;
  EXPECT_THROW(require_valid_mesh(m, true), Error);
}

} // namespace
} // namespace hoct
