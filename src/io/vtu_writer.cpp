#include "io/vtu_writer.hpp"

#include "io/atomic_file.hpp"
#include "poly/lagrange_node_order.hpp"
#include "util/error.hpp"

#include <string>

namespace hoct {

void write_vtu(const std::string &path, const MeshInput &m, VtkEncoding encoding) {
  const std::size_t np = m.points.size(), nc = m.num_cells();
  std::vector<double> points(3 * np);
  for (std::size_t i = 0; i < np; ++i)
    for (int a = 0; a < 3; ++a)
      points[3 * i + a] = m.points[i][a];
  std::vector<int64_t> connectivity(m.cell_nodes.size()), offsets(nc);
  std::vector<uint8_t> types(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    const int d = m.cell_degree[c];
    const CellKind kind = m.kind(c);
    const std::vector<int> *perm = nullptr;
    switch (kind) {
    case CellKind::LagrangeTriangle:
    case CellKind::BezierTriangle:
      perm = &node_order_to_lattice(NodeOrdering::Vtk, d);
      types[c] = kind == CellKind::BezierTriangle ? 76 : (d == 1 ? 5 : 69);
      break;
    case CellKind::LagrangeQuadrilateral:
    case CellKind::BezierQuadrilateral:
      perm = &quad_node_order_to_tensor(NodeOrdering::Vtk, d);
      types[c] = kind == CellKind::BezierQuadrilateral ? 77 : (d == 1 ? 9 : 70);
      break;
    case CellKind::SerendipityQuadrilateral:
      if (d != 2)
        throw InputError(path + ": cell " + std::to_string(c) +
                         " is a serendipity quadrilateral of order " + std::to_string(d) +
                         ", which VTK has no cell type for (only order 2: VTK_QUADRATIC_QUAD)");
      perm = &serendipity_node_order(NodeOrdering::Vtk, d);
      types[c] = 23;
      break;
    }
    const int64_t base = m.cell_offsets[c];
    for (std::size_t i = 0; i < perm->size(); ++i)
      connectivity[base + i] = m.cell_nodes[base + (*perm)[i]];
    offsets[c] = m.cell_offsets[c + 1];
  }
  VtkXmlArrays arrays(encoding);
  const std::string name = m.field_name.empty() ? "f" : m.field_name;
  const std::string e_values = arrays.array(name, m.values);
  const std::string e_points = arrays.array("Points", points, 3);
  const std::string e_conn = arrays.array("connectivity", connectivity);
  const std::string e_off = arrays.array("offsets", offsets);
  const std::string e_types = arrays.array("types", types);
  write_file_atomic(path, [&](std::ostream &out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
        << arrays.file_attributes() << ">\n <UnstructuredGrid>\n  <Piece NumberOfPoints=\"" << np
        << "\" NumberOfCells=\"" << nc << "\">\n   <PointData Scalars=\"" << xml_escape(name)
        << "\">\n    " << e_values << "\n   </PointData>\n   <Points>\n    " << e_points
        << "\n   </Points>\n   <Cells>\n    " << e_conn << "\n    " << e_off << "\n    " << e_types
        << "\n   </Cells>\n  </Piece>\n </UnstructuredGrid>\n";
    arrays.write_appended(out);
    out << "</VTKFile>\n";
  });
}

} // namespace hoct
