// io/vtk_cells: VTK triangle and quadrilateral cells become MeshInput cells whose nodes sit where
// the canonical order says (checked by position against VTK's documented node layouts), other cells
// are skipped or refused with a clear reason.
#include "io/vtk_cells.hpp"
#include "poly/lattice.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace hoct {
namespace {

// Points given in VTK order for one cell, stored in reverse so that ids differ from positions
// in the connectivity; checks every lattice node's position after the conversion.
void expect_lattice_positions(int64_t type, int degree, const std::vector<Vec3> &vtk_points) {
  MeshInput m;
  const int64_t n = static_cast<int64_t>(vtk_points.size());
  m.points.assign(vtk_points.rbegin(), vtk_points.rend());
  std::vector<int64_t> ids;
  for (int64_t i = 0; i < n; ++i)
    ids.push_back(n - 1 - i);
  std::string problem;
  ASSERT_EQ(add_vtk_cell(m, type, ids.data(), n, n, 0, &problem), VtkCellResult::Added) << problem;
  ASSERT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.cell_degree[0], degree);
  for (int b = 0; b <= degree; ++b)
    for (int a = 0; a + b <= degree; ++a) {
      const Vec3 &p = m.points[m.cell_nodes[lattice_index(degree, a, b)]];
      EXPECT_NEAR(p[0], double(a) / degree, 1e-15) << "type " << type << " node " << a << "," << b;
      EXPECT_NEAR(p[1], double(b) / degree, 1e-15) << "type " << type << " node " << a << "," << b;
    }
}

TEST(VtkCells, NodeLayoutsByPosition) {
  // VTK_TRIANGLE: the corners.
  expect_lattice_positions(5, 1, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  // VTK_QUADRATIC_TRIANGLE: corners, then the midpoints of edges 01, 12, 20.
  expect_lattice_positions(22, 2,
                           {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {.5, 0, 0}, {.5, .5, 0}, {0, .5, 0}});
  // VTK_LAGRANGE_TRIANGLE of degree 3: corners, two nodes per edge along 01, 12, 20, the centre.
  const double t = 1.0 / 3, s = 2.0 / 3;
  expect_lattice_positions(69, 3,
                           {{0, 0, 0},
                            {1, 0, 0},
                            {0, 1, 0},
                            {t, 0, 0},
                            {s, 0, 0},
                            {s, t, 0},
                            {t, s, 0},
                            {0, s, 0},
                            {0, t, 0},
                            {t, t, 0}});
}

// The same for a quadrilateral: the tensor node i + (p+1) j must sit at (i/p, j/p).
void expect_tensor_positions(int64_t type, int p, CellKind kind,
                             const std::vector<Vec3> &vtk_points) {
  MeshInput m;
  const int64_t n = static_cast<int64_t>(vtk_points.size());
  m.points.assign(vtk_points.rbegin(), vtk_points.rend());
  std::vector<int64_t> ids;
  for (int64_t i = 0; i < n; ++i)
    ids.push_back(n - 1 - i);
  std::string problem;
  ASSERT_EQ(add_vtk_cell(m, type, ids.data(), n, n, 0, &problem), VtkCellResult::Added) << problem;
  ASSERT_EQ(m.num_cells(), 1u);
  EXPECT_EQ(m.cell_degree[0], p);
  EXPECT_EQ(m.kind(0), kind);
  int k = 0;
  for (int j = 0; j <= p; ++j)
    for (int i = 0; i <= p; ++i) {
      const bool boundary = i == 0 || j == 0 || i == p || j == p;
      if (kind == CellKind::SerendipityQuadrilateral && !boundary)
        continue;
      const Vec3 &x = m.points[m.cell_nodes[k++]];
      EXPECT_NEAR(x[0], double(i) / p, 1e-15) << "type " << type << " node " << i << "," << j;
      EXPECT_NEAR(x[1], double(j) / p, 1e-15) << "type " << type << " node " << i << "," << j;
    }
}

TEST(VtkCells, QuadrilateralLayoutsByPosition) {
  // VTK_QUAD: counterclockwise corners.
  expect_tensor_positions(9, 1, CellKind::LagrangeQuadrilateral,
                          {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  // VTK_LAGRANGE_QUADRILATERAL of order 3 (vtkHigherOrderQuadrilateral's numbering): corners,
  // the nodes of edges (0,0)-(1,0), (1,0)-(1,1), (0,1)-(1,1), (0,0)-(0,1), each along increasing
  // s or t, then the interior, s fastest.
  const double t = 1.0 / 3, u = 2.0 / 3;
  expect_tensor_positions(70, 3, CellKind::LagrangeQuadrilateral,
                          {{0, 0, 0},
                           {1, 0, 0},
                           {1, 1, 0},
                           {0, 1, 0},
                           {t, 0, 0},
                           {u, 0, 0},
                           {1, t, 0},
                           {1, u, 0},
                           {t, 1, 0},
                           {u, 1, 0},
                           {0, t, 0},
                           {0, u, 0},
                           {t, t, 0},
                           {u, t, 0},
                           {t, u, 0},
                           {u, u, 0}});
  // VTK_QUADRATIC_QUAD: corners, then the midpoints of edges 01, 12, 23, 30.
  const std::vector<Vec3> q8 = {{0, 0, 0},  {1, 0, 0},  {1, 1, 0},  {0, 1, 0},
                                {.5, 0, 0}, {1, .5, 0}, {.5, 1, 0}, {0, .5, 0}};
  expect_tensor_positions(23, 2, CellKind::SerendipityQuadrilateral, q8);
  // VTK_BIQUADRATIC_QUAD: the same and the centre.
  std::vector<Vec3> q9 = q8;
  q9.push_back({.5, .5, 0});
  expect_tensor_positions(28, 2, CellKind::LagrangeQuadrilateral, q9);
}

TEST(VtkCells, BaseOffsetsIds) {
  MeshInput m;
  const int64_t ids[3] = {0, 1, 2};
  std::string problem;
  ASSERT_EQ(add_vtk_cell(m, 5, ids, 3, 3, 10, &problem), VtkCellResult::Added);
  EXPECT_EQ(m.cell_nodes, (PooledVector<int64_t>{10, 11, 12}));
}

TEST(VtkCells, SkipsVerticesAndLinesRefusesTheRest) {
  MeshInput m;
  const int64_t ids[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  std::string problem;
  for (int64_t type : {1, 3, 21, 68})
    EXPECT_EQ(add_vtk_cell(m, type, ids, 2, 10, 0, &problem), VtkCellResult::Skipped);
  EXPECT_EQ(m.num_cells(), 0u);
  auto refused = [&](int64_t type, int64_t n, int64_t num_points, const std::string &why) {
    problem.clear();
    EXPECT_EQ(add_vtk_cell(m, type, ids, n, num_points, 0, &problem), VtkCellResult::Invalid);
    EXPECT_NE(problem.find(why), std::string::npos) << problem;
    EXPECT_EQ(m.num_cells(), 0u);
  };
  refused(10, 4, 10, "VTK cell type 10, which is not a supported surface cell");
  refused(70, 8, 10, "HigherOrderDegrees");
  refused(9, 5, 10, "of type 9 has 5 nodes");
  refused(23, 9, 10, "has 9 nodes, not 8");
  refused(22, 7, 10, "of type 22 has 7 nodes");
  refused(69, 7, 10, "'bubble' triangle");
  refused(69, 8, 10, "not a complete triangle");
  refused(5, 3, 2, "refers to point 2, but the piece has 2 points");
}

} // namespace
} // namespace hoct
