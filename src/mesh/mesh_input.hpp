// The format-free description of a higher-order surface mesh with a scalar field, as readers
// produce it and generators build it. Cells are triangles or quadrilaterals, Lagrange (nodal
// values) or Bezier (control values), their nodes in a canonical order: the triangle lattice
// order of poly/lattice.hpp, or for a quadrilateral of bidegree (p, p) the tensor order i + (p+1)j
// of the node at (i/p, j/p) of the unit square (corners (0,0), (1,0), (1,1), (0,1) at 0, p,
// (p+1)^2 - 1, p(p+1)). Readers convert from VTK or Gmsh order with poly/lagrange_node_order.hpp.
// The core never sees a file format; mesh/cell_split turns quadrilaterals and Bezier cells into
// Lagrange triangles carrying the same polynomials before anything else looks at the cells.
#pragma once

#include "util/fingerprint.hpp"
#include "util/uninitialized_vector.hpp"
#include "util/vec.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hoct {

enum class CellKind : uint8_t {
  LagrangeTriangle = 0,      // (d+1)(d+2)/2 nodal values, lattice order
  BezierTriangle = 1,        // (d+1)(d+2)/2 Bernstein control values and points, lattice order
  LagrangeQuadrilateral = 2, // (p+1)^2 nodal values, tensor order, bidegree (p, p)
  BezierQuadrilateral = 3,   // (p+1)^2 tensor Bernstein control values and points
  // Serendipity (incomplete) quadrilateral of order p >= 2: the 4p boundary nodes of the tensor
  // grid, in tensor order (poly/quad_basis.hpp: quad_boundary_indices).
  SerendipityQuadrilateral = 4,
};
constexpr bool is_quadrilateral(CellKind k) {
  return k == CellKind::LagrangeQuadrilateral || k == CellKind::BezierQuadrilateral ||
         k == CellKind::SerendipityQuadrilateral;
}
constexpr bool is_bezier(CellKind k) {
  return k == CellKind::BezierTriangle || k == CellKind::BezierQuadrilateral;
}
// Nodes of a cell of this kind and degree (bidegree (d, d) for a quadrilateral).
constexpr int cell_node_count(CellKind k, int d) {
  return k == CellKind::SerendipityQuadrilateral
             ? 4 * d
             : (is_quadrilateral(k) ? (d + 1) * (d + 1) : (d + 1) * (d + 2) / 2);
}
// "triangle", "Bezier quadrilateral", ...
const char *cell_kind_name(CellKind k);

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
  // The same for the stored values: 2^-24 for float32 arrays, 0 for doubles (and integers, and
  // text whose digits cannot be known). The field's precision (Field::precision) counts it.
  double value_precision = 0;
  // The fingerprint of the data as read, where they were changed since (GLL nodes resampled,
  // mesh/gll_nodes): mesh_fingerprint gives it, so that a tree records the file's data.
  std::optional<InputFingerprint> read_fingerprint;

  // Cells in compressed-row form: the nodes of cell c are
  // cell_nodes[cell_offsets[c] .. cell_offsets[c+1]), cell_node_count(kind(c), d) of them for
  // degree d, in canonical order.
  PooledVector<int64_t> cell_offsets{0};
  PooledVector<int64_t> cell_nodes;
  PooledVector<uint8_t> cell_degree;
  // Each cell's CellKind; empty when every cell is a Lagrange triangle (most meshes: no array).
  PooledVector<uint8_t> cell_kind;

  std::size_t num_cells() const { return cell_degree.size(); }
  std::size_t num_points() const { return points.size(); }
  CellKind kind(std::size_t c) const {
    return cell_kind.empty() ? CellKind::LagrangeTriangle : static_cast<CellKind>(cell_kind[c]);
  }
  // No quadrilateral and no Bezier cell.
  bool lagrange_triangles_only() const;

  // Appends a Lagrange triangle whose nodes are already in canonical lattice order.
  void add_cell(int degree, const int64_t *nodes);
  // Appends a cell of any kind, its nodes in canonical order.
  void add_cell(CellKind kind, int degree, const int64_t *nodes);
  // Records cell c's kind (the cell already appended): the kind array is created on the first
  // cell that is not a Lagrange triangle.
  void set_kind(std::size_t c, CellKind kind);
};

} // namespace hoct
