#include "io/tree_vtp_writer.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_xml_arrays.hpp"

#include <algorithm>

namespace hoct {

void write_tree_vtp(const std::string &path, const TreeResult &t) {
  const std::size_t n = t.nodes.size(), m = t.arcs.size();
  std::vector<double> points(3 * n), value(n), node_pers(n, 0.0), arc_pers(m);
  std::vector<int32_t> type(n), location(n), fallback(n);
  std::vector<int64_t> ids(n), cell(n), verts(n), vert_offsets(n), lines(2 * m), line_offsets(m);
  for (const auto &p : t.pairs) {
    node_pers[p.birth] = std::max(node_pers[p.birth], p.persistence());
    node_pers[p.death] = std::max(node_pers[p.death], p.persistence());
  }
  for (std::size_t i = 0; i < n; ++i) {
    const TreeNode &nd = t.nodes[i];
    std::copy(nd.position.begin(), nd.position.end(), points.begin() + 3 * i);
    value[i] = nd.value;
    type[i] = static_cast<int32_t>(nd.type);
    location[i] = static_cast<int32_t>(nd.location);
    fallback[i] = nd.fallback ? 1 : 0;
    ids[i] = static_cast<int64_t>(i);
    cell[i] = nd.cell;
    verts[i] = static_cast<int64_t>(i);
    vert_offsets[i] = static_cast<int64_t>(i + 1);
  }
  for (std::size_t a = 0; a < m; ++a) {
    lines[2 * a] = t.arcs[a][0];
    lines[2 * a + 1] = t.arcs[a][1];
    line_offsets[a] = static_cast<int64_t>(2 * a + 2);
    arc_pers[a] = std::min(node_pers[t.arcs[a][0]], node_pers[t.arcs[a][1]]);
  }
  VtkXmlArrays data(VtkEncoding::AppendedRaw);
  const std::string e_points = data.array("Points", points, 3);
  const std::string e_type = data.array("type", type), e_value = data.array("value", value),
                    e_pers = data.array("persistence", node_pers),
                    e_id = data.array("node_id", ids), e_cell = data.array("cell", cell),
                    e_loc = data.array("location", location),
                    e_fb = data.array("fallback", fallback);
  // Cell data is ordered verts first, then lines: vertices get their node's persistence.
  std::vector<double> cell_pers(node_pers);
  cell_pers.insert(cell_pers.end(), arc_pers.begin(), arc_pers.end());
  const std::string e_cpers = data.array("persistence", cell_pers);
  const std::string e_vc = data.array("connectivity", verts),
                    e_vo = data.array("offsets", vert_offsets),
                    e_lc = data.array("connectivity", lines),
                    e_lo = data.array("offsets", line_offsets);
  write_file_atomic(path, [&](std::ostream &out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" " << data.file_attributes() << ">\n"
        << " <PolyData>\n"
        << "  <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n << "\" NumberOfLines=\""
        << m << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "   <PointData Scalars=\"value\">\n    " << e_type << "\n    " << e_value << "\n    "
        << e_pers << "\n    " << e_id << "\n    " << e_cell << "\n    " << e_loc << "\n    " << e_fb
        << "\n   </PointData>\n"
        << "   <CellData>\n    " << e_cpers << "\n   </CellData>\n"
        << "   <Points>\n    " << e_points << "\n   </Points>\n"
        << "   <Verts>\n    " << e_vc << "\n    " << e_vo << "\n   </Verts>\n"
        << "   <Lines>\n    " << e_lc << "\n    " << e_lo << "\n   </Lines>\n"
        << "  </Piece>\n </PolyData>\n";
    data.write_appended(out);
    out << "</VTKFile>\n";
  });
}

} // namespace hoct
