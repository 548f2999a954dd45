#include "io/tree_vtp_writer.hpp"

#include "io/atomic_file.hpp"
#include "io/tree_polydata.hpp"
#include "io/vtk_xml_arrays.hpp"

namespace hoct {
namespace {

template <class To, class From> std::vector<To> cast_all(const std::vector<From> &v) {
  std::vector<To> r(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    r[i] = static_cast<To>(v[i]);
  return r;
}

} // namespace

void write_tree_vtp(const std::string &path, const TreeResult &t) {
  const TreePolyData d = tree_polydata(t);
  const std::size_t n = d.num_nodes, np = d.num_points(), m = d.num_lines();
  std::vector<int64_t> verts(n), vert_offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    verts[i] = static_cast<int64_t>(i);
    vert_offsets[i] = static_cast<int64_t>(i + 1);
  }
  VtkXmlArrays data(VtkEncoding::AppendedRaw);
  const std::string e_points = data.array("Points", d.points, 3);
  const std::string e_type = data.array("type", cast_all<int32_t>(d.type)),
                    e_value = data.array("value", d.value),
                    e_pers = data.array("persistence", d.persistence),
                    e_id = data.array("node_id", d.node_id), e_cell = data.array("cell", d.cell),
                    e_loc = data.array("location", cast_all<int32_t>(d.location)),
                    e_fb = data.array("fallback", cast_all<int32_t>(d.fallback));
  // Cell data is ordered verts first, then lines: vertices get their node's persistence.
  std::vector<double> cell_pers(d.node_persistence);
  cell_pers.insert(cell_pers.end(), d.arc_persistence.begin(), d.arc_persistence.end());
  const std::string e_cpers = data.array("persistence", cell_pers);
  const std::string e_vc = data.array("connectivity", verts),
                    e_vo = data.array("offsets", vert_offsets),
                    e_lc = data.array("connectivity", d.line_connectivity),
                    e_lo = data.array("offsets", d.line_offsets);
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
