// mesh/domain_check: a disk and a sphere pass, two components do not.
#include "datasets/datasets.hpp"
#include "mesh/domain_check.hpp"
#include "mesh/mesh.hpp"

#include <gtest/gtest.h>

namespace hoct {
namespace {

TEST(DomainCheck, DiskAndSpherePassTwoComponentsDoNot) {
  for (const char *name : {"two-triangle", "sphere"}) {
    const Mesh mesh = build_mesh(generate_dataset(name, {}));
    EXPECT_EQ(domain_problem(mesh.topology), "") << name;
  }
  MeshInput two;
  two.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  two.values = {0, 1, 2, 3, 4, 5};
  const int64_t a[3] = {0, 1, 2}, b[3] = {3, 4, 5};
  two.add_cell(1, a);
  two.add_cell(1, b);
  const std::string problem = domain_problem(build_mesh(two).topology);
  EXPECT_NE(problem.find("not a disk or a sphere but 2 separate components: 2 component(s)"),
            std::string::npos)
      << problem;
}

} // namespace
} // namespace hoct
