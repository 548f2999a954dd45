#include "io/tree_vtp_writer.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_xml_arrays.hpp"

#include <algorithm>

namespace hoct {

void write_tree_vtp(const std::string &path, const TreeResult &t) {
  const std::size_t n = t.nodes.size(), m = t.arcs.size();
  const bool curved = t.arc_paths.size() == m && m > 0;
  // Points: the nodes first, then the interior points of the arcs' polylines.
  std::size_t extra = 0;
  if (curved)
    for (const auto &p : t.arc_paths)
      extra += p.size() > 2 ? p.size() - 2 : 0;
  const std::size_t np = n + extra;
  std::vector<double> points(3 * np), value(np), node_pers(n, 0.0), point_pers(np, 0.0),
      arc_pers(m);
  std::vector<int32_t> type(np, static_cast<int32_t>(NodeType::Regular)),
      location(np, static_cast<int32_t>(NodeLocation::Unknown)), fallback(np, 0);
  std::vector<int64_t> ids(np, -1), cell(np, -1), verts(n), vert_offsets(n), lines, line_offsets(m);
  for (const auto &p : t.pairs) {
    node_pers[p.birth] = std::max(node_pers[p.birth], p.persistence());
    node_pers[p.death] = std::max(node_pers[p.death], p.persistence());
  }
  for (std::size_t i = 0; i < n; ++i) {
    const TreeNode &nd = t.nodes[i];
    std::copy(nd.position.begin(), nd.position.end(), points.begin() + 3 * i);
    value[i] = nd.value;
    point_pers[i] = node_pers[i];
    type[i] = static_cast<int32_t>(nd.type);
    location[i] = static_cast<int32_t>(nd.location);
    fallback[i] = nd.fallback ? 1 : 0;
    ids[i] = static_cast<int64_t>(i);
    cell[i] = nd.cell;
    verts[i] = static_cast<int64_t>(i);
    vert_offsets[i] = static_cast<int64_t>(i + 1);
  }
  std::size_t next = n;
  for (std::size_t a = 0; a < m; ++a) {
    const int64_t lo = t.arcs[a][0], hi = t.arcs[a][1];
    arc_pers[a] = std::min(node_pers[lo], node_pers[hi]);
    lines.push_back(lo);
    if (curved) {
      // Interior points of the polyline; values interpolated along it (for colouring).
      const auto &p = t.arc_paths[a];
      for (std::size_t k = 1; k + 1 < p.size(); ++k) {
        std::copy(p[k].begin(), p[k].end(), points.begin() + 3 * next);
        const double f = static_cast<double>(k) / static_cast<double>(p.size() - 1);
        value[next] = t.nodes[lo].value + f * (t.nodes[hi].value - t.nodes[lo].value);
        point_pers[next] = arc_pers[a];
        lines.push_back(static_cast<int64_t>(next++));
      }
    }
    lines.push_back(hi);
    line_offsets[a] = static_cast<int64_t>(lines.size());
  }
  VtkXmlArrays data(VtkEncoding::AppendedRaw);
  const std::string e_points = data.array("Points", points, 3);
  const std::string e_type = data.array("type", type), e_value = data.array("value", value),
                    e_pers = data.array("persistence", point_pers),
                    e_id = data.array("node_id", ids), e_cell = data.array("cell", cell),
                    e_loc = data.array("location", location),
                    e_fb = data.array("fallback", fallback);
  // Cell data is ordered verts first, then lines: vertices get their node's persistence.
  std::vector<double> cell_pers(node_pers.begin(), node_pers.end());
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
        << "  <Piece NumberOfPoints=\"" << np << "\" NumberOfVerts=\"" << n << "\" NumberOfLines=\""
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
