#include "vtkio/xdmf_copy.hpp"

#include "util/error.hpp"

#include <pugixml.hpp>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace hoct {

namespace {

std::string trimmed(std::string s) {
  s.erase(0, s.find_first_not_of(" \t\r\n"));
  s.erase(s.find_last_not_of(" \t\r\n") + 1);
  return s;
}

} // namespace

XdmfForReading::XdmfForReading(const std::string &path) {
  namespace fs = std::filesystem;
  // Xdmf resolves the HDF5 file next to the .xdmf wrongly for a name without a directory
  // ("f.xdmff.h5"): an absolute path.
  path_ = fs::absolute(path).string();
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_file(path.c_str());
  if (!parsed)
    throw InputError(path + ": not valid XML: " + parsed.description() + " at byte " +
                     std::to_string(parsed.offset));
  const fs::path dir = fs::path(path_).parent_path();
  for (const pugi::xpath_node &x : doc.select_nodes("//DataItem")) {
    pugi::xml_node item = x.node();
    const std::string format = item.attribute("Format").as_string("XML");
    const std::string type = item.attribute("NumberType").as_string("Float");
    if (type == "Float" && !item.attribute("Precision")) { // both, or Xdmf ignores Precision
      if (!item.attribute("NumberType"))
        item.append_attribute("NumberType") = "Float";
      item.append_attribute("Precision") = "8";
      ++widened_;
    }
    if (format != "HDF")
      continue;
    const std::string text = trimmed(item.text().as_string());
    const std::size_t colon = text.find(':');
    const std::string file = text.substr(0, colon);
    if (file.empty())
      throw InputError(path + ": a DataItem of Format HDF names no file");
    const fs::path full = fs::path(file).is_absolute() ? fs::path(file) : dir / file;
    if (!fs::is_regular_file(full))
      throw InputError(path + ": its HDF5 file '" + file + "' is missing (looked for " +
                       full.string() + ")");
    item.text().set(
        (full.string() + (colon == std::string::npos ? "" : text.substr(colon))).c_str());
  }
  if (widened_ == 0)
    return;
  std::string name = (fs::temp_directory_path() / "hoct-XXXXXX.xdmf").string();
  const int fd = mkstemps(name.data(), 5);
  if (fd < 0)
    throw Error(path + ": cannot create a temporary copy in " + fs::temp_directory_path().string());
  close(fd);
  if (!doc.save_file(name.c_str(), "  ")) {
    std::error_code ec;
    fs::remove(name, ec);
    throw Error(path + ": cannot write its temporary copy " + name);
  }
  path_ = name;
  copy_ = true;
}

XdmfForReading::~XdmfForReading() {
  if (copy_) {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
}

} // namespace hoct
