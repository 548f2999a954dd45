#include "io/read_mesh.hpp"

#include "io/external_reader.hpp"
#include "io/file_bytes.hpp"
#include "io/msh_reader.hpp"
#include "io/pos_reader.hpp"
#include "io/pvd_reader.hpp"
#include "io/pvtu_reader.hpp"
#include "io/vtu_reader.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <filesystem>

namespace hoct {

MeshInput read_mesh(const std::string &path, const FieldSelection &field, const ReadLimits &limits,
                    FileContents *contents) {
  if (const std::string what = special_file(path); !what.empty())
    throw InputError(path + ": " + what);
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".vtu")
    return read_vtu(path, field, limits);
  if (ext == ".pvtu")
    return read_pvtu(path, field, limits);
  if (ext == ".pvd")
    return read_pvd(path, field, limits);
  if (ext == ".msh")
    return read_msh(path, field, limits, contents);
  if (ext == ".pos")
    return read_pos(path, field, limits, contents);
  const ExternalReader *external = external_reader();
  if (external && std::find(external->extensions.begin(), external->extensions.end(), ext) !=
                      external->extensions.end())
    return external->read(path, field, limits, contents);
  throw InputError(path + ": unknown file type '" + ext +
                   "' (supported: .vtu VTK XML UnstructuredGrid, .pvtu its pieces, .pvd a "
                   "collection of them, .msh Gmsh 4.1 or 2.2, .pos Gmsh parsed views" +
                   (external ? "; through " + external->name + ": " + external->formats
                             : std::string("; this hoct was built without VTK, whose readers "
                                           "read legacy .vtk, XDMF and Exodus II")) +
                   ")");
}

} // namespace hoct
