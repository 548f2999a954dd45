// A piecewise-linear scalar field on a triangle mesh: vertex positions and values, triangles.
// The input of the PL contour tree; built from a file's linear cells, by splitting higher-order
// cells through their Lagrange nodes, or by refining the exact field (pl/refinement.hpp).
#pragma once

#include "mesh/mesh_input.hpp"
#include "tree/scalar_graph.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hoct {

struct PlMesh {
  std::vector<Vec3> points;
  std::vector<double> values;
  // values[i] + reference is the field's value at point i: refine() keeps the exact field's
  // values relative to its reference (mesh/field.hpp); the trees and writers add it back.
  double reference = 0;
  std::vector<std::array<int64_t, 3>> triangles;
  // Where each vertex comes from in the higher-order mesh (for reports): the cell and the
  // parametric position in it; -1 if unknown.
  std::vector<int64_t> source_cell;
  std::vector<std::array<double, 2>> source_uv;

  int64_t num_vertices() const { return static_cast<int64_t>(values.size()); }
  // The 1-skeleton as a scalar graph (every triangle edge once).
  ScalarGraph graph() const;
};

// The PL mesh as linear cells (for writers and for the mesh checks).
MeshInput to_mesh_input(const PlMesh &pl);

// Each Lagrange cell of degree d split into d^2 linear triangles through its nodes (the "linear
// interpretation" of the input's nodes); a quadrilateral of bidegree (d, d) into 2 d^2, each
// square of its node grid cut along the diagonal from its (i, j) node to its (i+1, j+1) node
// (Bezier and serendipity cells through nodal_cells: mesh/cell_split.hpp). Vertices name the
// first input cell that has them and their (u, v) or (s, t) in it (the cell the exact tree
// places a vertex node in, on a mesh of linear triangles). Points no cell uses are left out
// (the others keep their order), unless keep_unused_points (then their source_cell is -1).
PlMesh split_lagrange_cells(const MeshInput &input, bool keep_unused_points = false);

// Whether every cell is a Lagrange triangle or quadrilateral: split_lagrange_cells then makes no
// points of its own (the vertices are the input's points, with their values as read).
bool nodal_lagrange_cells(const MeshInput &input);

} // namespace hoct
