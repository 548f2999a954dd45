#include "io/vtk_xml_appended.hpp"

#include <cstring>

namespace hoct {

static_assert(sizeof(double) == 8);

std::string VtkAppendedData::add(const std::string &name, const char *type, const void *data,
                                 std::size_t bytes, int components) {
  const std::size_t offset = bytes_.size();
  const uint64_t header = bytes;
  const char *h = reinterpret_cast<const char *>(&header);
  bytes_.insert(bytes_.end(), h, h + sizeof(header));
  const char *d = static_cast<const char *>(data);
  bytes_.insert(bytes_.end(), d, d + bytes);
  std::string e = "<DataArray type=\"" + std::string(type) + "\" Name=\"" + xml_escape(name) +
                  "\" NumberOfComponents=\"" + std::to_string(components) +
                  "\" format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>";
  return e;
}

std::string VtkAppendedData::array(const std::string &name, const std::vector<double> &v,
                                   int components) {
  return add(name, "Float64", v.data(), v.size() * sizeof(double), components);
}
std::string VtkAppendedData::array(const std::string &name, const std::vector<int64_t> &v,
                                   int components) {
  return add(name, "Int64", v.data(), v.size() * sizeof(int64_t), components);
}
std::string VtkAppendedData::array(const std::string &name, const std::vector<int32_t> &v,
                                   int components) {
  return add(name, "Int32", v.data(), v.size() * sizeof(int32_t), components);
}
std::string VtkAppendedData::array(const std::string &name, const std::vector<uint8_t> &v,
                                   int components) {
  return add(name, "UInt8", v.data(), v.size(), components);
}

void VtkAppendedData::write(std::ostream &out) const {
  out << "  <AppendedData encoding=\"raw\">\n   _";
  out.write(bytes_.data(), static_cast<std::streamsize>(bytes_.size()));
  out << "\n  </AppendedData>\n";
}

std::string xml_escape(const std::string &s) {
  std::string r;
  for (char c : s) {
    switch (c) {
    case '&':
      r += "&amp;";
      break;
    case '<':
      r += "&lt;";
      break;
    case '>':
      r += "&gt;";
      break;
    case '"':
      r += "&quot;";
      break;
    default:
      r += c;
    }
  }
  return r;
}

} // namespace hoct
