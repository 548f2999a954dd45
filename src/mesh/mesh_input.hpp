// The format-free description of a higher-order triangle mesh with a scalar field, as readers
// produce it and generators build it. Cells are Lagrange triangles whose nodes are given in the
// canonical lattice order (see poly/lattice.hpp); readers convert from VTK or Gmsh order with
// poly/lagrange_node_order.hpp. The core never sees a file format.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

using Vec3 = std::array<double, 3>;

struct MeshInput {
  // Every node of the mesh (corner and higher-order nodes), with its 3D position and field value.
  std::vector<Vec3> points;
  std::vector<double> values;
  std::string field_name; // name of the scalar array, for reports
  std::string source;     // file name or generator description, for messages

  // Cells in compressed-row form: the nodes of cell c are
  // cell_nodes[cell_offsets[c] .. cell_offsets[c+1]), (d+1)(d+2)/2 of them for degree d,
  // in canonical lattice order (the three corners first).
  std::vector<int64_t> cell_offsets{0};
  std::vector<int64_t> cell_nodes;
  std::vector<uint8_t> cell_degree;

  std::size_t num_cells() const { return cell_degree.size(); }
  std::size_t num_points() const { return points.size(); }

  // Appends a cell whose nodes are already in canonical lattice order.
  void add_cell(int degree, const int64_t *nodes);
};

} // namespace hoct
