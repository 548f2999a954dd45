// The format-free description of a higher-order triangle mesh with a scalar field, as readers
// produce it and generators build it. Cells are Lagrange triangles whose nodes are given in the
// canonical lattice order (see poly/lattice.hpp); readers convert from VTK or Gmsh order with
// poly/lagrange_node_order.hpp. The core never sees a file format.
#pragma once

#include "util/uninitialized_vector.hpp"
#include "util/vec.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

// Its arrays' large buffers come from the page pool (util/page_pool.hpp): inside a PageReuseScope
// around reading, building and computing, the pages of the input the mesh build consumes serve
// the arrays built after it.
struct MeshInput {
  // Every node of the mesh (corner and higher-order nodes), with its 3D position and field value.
  PooledVector<Vec3> points;
  PooledVector<double> values;
  std::string field_name; // name of the scalar array, for reports
  std::string source;     // file name or generator description, for messages
  // Which time step of a file holding several was read ("(step 2 of 3, time 0.2)", "(step 4 of 5,
  // time 0.4: F_4.pvtu)"), for the summaries; empty for a file of one.
  std::string field_detail;
  // What the reader found worth telling but read anyway (one piece of a partitioned output read
  // alone, ...): complete sentences, which the front ends print as warnings.
  std::vector<std::string> warnings;
  // The rounding unit of the stored coordinates relative to their magnitude: 2^-24 for float32
  // files, 0 for doubles. Straight cells of a float32 file are straight within it (Geometry).
  double coordinate_precision = 0;

  // Cells in compressed-row form: the nodes of cell c are
  // cell_nodes[cell_offsets[c] .. cell_offsets[c+1]), (d+1)(d+2)/2 of them for degree d,
  // in canonical lattice order (the three corners first).
  PooledVector<int64_t> cell_offsets{0};
  PooledVector<int64_t> cell_nodes;
  PooledVector<uint8_t> cell_degree;

  std::size_t num_cells() const { return cell_degree.size(); }
  std::size_t num_points() const { return points.size(); }

  // Appends a cell whose nodes are already in canonical lattice order.
  void add_cell(int degree, const int64_t *nodes);
};

} // namespace hoct
