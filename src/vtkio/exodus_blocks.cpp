#include "vtkio/exodus_blocks.hpp"

#include "util/error.hpp"

#include <netcdf.h>
#include <netcdf_mem.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <vector>

namespace hoct {

namespace {

// The file mapped into memory (read-only, its pages read only where touched) and opened by
// netCDF from there: a read past the end of a truncated file is then an error, where netCDF
// reading the file itself fills the missing bytes with zeros.
struct NcFile {
  int id = -1;
  void *map = MAP_FAILED;
  std::size_t size = 0;
  ~NcFile() {
    if (id >= 0)
      nc_close(id);
    if (map != MAP_FAILED)
      munmap(map, size);
  }
};

void open_mapped(const std::string &path, NcFile &f) {
  const int fd = open(path.c_str(), O_RDONLY);
  struct stat st {};
  if (fd < 0 || fstat(fd, &st) != 0 || st.st_size <= 0) {
    if (fd >= 0)
      close(fd);
    throw InputError(path + ": cannot read it as an Exodus II file (empty or unreadable)");
  }
  f.size = static_cast<std::size_t>(st.st_size);
  f.map = mmap(nullptr, f.size, PROT_READ, MAP_PRIVATE, fd, 0);
  close(fd);
  if (f.map == MAP_FAILED)
    throw InputError(path + ": cannot map it into memory");
  if (const int status = nc_open_mem(path.c_str(), NC_NOWRITE, f.size, f.map, &f.id);
      status != NC_NOERR) {
    f.id = -1;
    throw InputError(path + ": netCDF cannot open it as an Exodus II file: " + nc_strerror(status));
  }
}

// Every variable's last value must be in the file (a truncated file's are not).
void check_extents(const std::string &path, int file) {
  int vars = 0;
  if (nc_inq_nvars(file, &vars) != NC_NOERR)
    throw InputError(path + ": netCDF cannot list its variables");
  for (int v = 0; v < vars; ++v) {
    int ndims = 0;
    if (nc_inq_varndims(file, v, &ndims) != NC_NOERR || ndims > NC_MAX_VAR_DIMS)
      throw InputError(path + ": netCDF cannot read variable " + std::to_string(v));
    std::vector<int> dims(static_cast<std::size_t>(ndims));
    std::vector<std::size_t> last(dims.size(), 0);
    nc_inq_vardimid(file, v, dims.data());
    bool empty = false;
    for (std::size_t k = 0; k < dims.size(); ++k) {
      std::size_t len = 0;
      nc_inq_dimlen(file, dims[k], &len);
      empty = empty || len == 0;
      last[k] = len ? len - 1 : 0;
    }
    if (empty)
      continue;
    nc_type type = 0;
    std::size_t bytes = 0;
    char value[64];
    if (nc_inq_vartype(file, v, &type) != NC_NOERR || nc_inq_type(file, type, nullptr, &bytes) ||
        bytes > sizeof value)
      continue; // a user-defined type (netCDF-4): not Exodus data
    if (const int status = nc_get_var1(file, v, last.data(), value); status != NC_NOERR) {
      char name[NC_MAX_NAME + 1] = "";
      nc_inq_varname(file, v, name);
      throw InputError(path + ": variable '" + name +
                       "' ends past the end of the file (truncated?): " + nc_strerror(status));
    }
  }
}

int64_t dimension(int file, const std::string &name) {
  int dim = 0;
  std::size_t len = 0;
  if (nc_inq_dimid(file, name.c_str(), &dim) != NC_NOERR || nc_inq_dimlen(file, dim, &len))
    return -1;
  return static_cast<int64_t>(len);
}

} // namespace

std::vector<ExodusBlock> exodus_element_blocks(const std::string &path) {
  NcFile f;
  open_mapped(path, f);
  check_extents(path, f.id);
  std::vector<ExodusBlock> blocks;
  const int64_t n = dimension(f.id, "num_el_blk");
  for (int64_t i = 1; i <= n; ++i) {
    ExodusBlock b;
    b.index = static_cast<int>(i);
    const std::string k = std::to_string(i);
    b.elements = std::max<int64_t>(0, dimension(f.id, "num_el_in_blk" + k));
    b.nodes_per_element =
        static_cast<int>(std::max<int64_t>(0, dimension(f.id, "num_nod_per_el" + k)));
    int var = 0;
    std::size_t len = 0;
    if (nc_inq_varid(f.id, ("connect" + k).c_str(), &var) == NC_NOERR &&
        nc_inq_attlen(f.id, var, "elem_type", &len) == NC_NOERR && len < 4096) {
      std::string text(len, '\0');
      if (nc_get_att_text(f.id, var, "elem_type", text.data()) == NC_NOERR)
        b.elem_type = text.substr(0, text.find('\0'));
    }
    blocks.push_back(std::move(b));
  }
  return blocks;
}

} // namespace hoct
