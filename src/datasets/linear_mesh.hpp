// Linear triangle meshes the generators start from (a jittered square grid with optional holes,
// a subdivided icosahedron), and their lifting to Lagrange meshes of any degree: one point per
// vertex, d-1 points per edge created once and shared by both cells, interior points per cell;
// positions through a placement map (flat point -> surface point) so curved cells come out right.
#pragma once

#include "mesh/mesh_input.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace hoct {

struct LinearMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int64_t, 3>> triangles; // counter-clockwise (outward on surfaces)
};

// nx x ny squares of size h starting at (x0, y0), each split into two triangles with
// alternating diagonals; squares where keep(i, j) is false are left out; interior vertices
// (not on the outer or a hole's boundary) jittered by up to `jitter` * h. Unused vertices are
// dropped.
LinearMesh square_grid(int nx, int ny, double h, double x0, double y0, double jitter, uint64_t seed,
                       const std::function<bool(int, int)> &keep = nullptr);

// An icosahedron with every face split into n^2 triangles, vertices on the unit sphere.
LinearMesh icosphere(int n);

using Placement = std::function<Vec3(const Vec3 &)>;
using ScalarFunction = std::function<double(const Vec3 &)>;

// Lifts a linear mesh to degree d: node positions are place(flat position) (identity if empty),
// values f(position).
MeshInput lagrange_mesh(const LinearMesh &mesh, int degree, const Placement &place,
                        const ScalarFunction &f);

} // namespace hoct
