#include "mesh/mesh_input.hpp"

#include "poly/lattice.hpp"

#include <algorithm>

namespace hoct {

const char *cell_kind_name(CellKind k) {
  switch (k) {
  case CellKind::LagrangeTriangle:
    return "triangle";
  case CellKind::BezierTriangle:
    return "Bezier triangle";
  case CellKind::LagrangeQuadrilateral:
    return "quadrilateral";
  case CellKind::BezierQuadrilateral:
    return "Bezier quadrilateral";
  case CellKind::SerendipityQuadrilateral:
    return "serendipity quadrilateral";
  }
  return "cell";
}

bool MeshInput::lagrange_triangles_only() const {
  return std::all_of(cell_kind.begin(), cell_kind.end(), [](uint8_t k) {
    return static_cast<CellKind>(k) == CellKind::LagrangeTriangle;
  });
}

void MeshInput::add_cell(int degree, const int64_t *nodes) {
  const int n = lattice_size(degree);
  cell_nodes.insert(cell_nodes.end(), nodes, nodes + n);
  cell_offsets.push_back(static_cast<int64_t>(cell_nodes.size()));
  cell_degree.push_back(static_cast<uint8_t>(degree));
  if (!cell_kind.empty())
    cell_kind.push_back(static_cast<uint8_t>(CellKind::LagrangeTriangle));
}

void MeshInput::add_cell(CellKind kind, int degree, const int64_t *nodes) {
  const int n = cell_node_count(kind, degree);
  cell_nodes.insert(cell_nodes.end(), nodes, nodes + n);
  cell_offsets.push_back(static_cast<int64_t>(cell_nodes.size()));
  cell_degree.push_back(static_cast<uint8_t>(degree));
  set_kind(cell_degree.size() - 1, kind);
}

void MeshInput::set_kind(std::size_t c, CellKind kind) {
  if (cell_kind.empty()) {
    if (kind == CellKind::LagrangeTriangle)
      return;
    cell_kind.assign(c, static_cast<uint8_t>(CellKind::LagrangeTriangle));
  }
  if (cell_kind.size() <= c)
    cell_kind.resize(c + 1, static_cast<uint8_t>(CellKind::LagrangeTriangle));
  cell_kind[c] = static_cast<uint8_t>(kind);
}

} // namespace hoct
