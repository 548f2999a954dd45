// Building blocks for VTK XML files with appended raw binary data (header_type UInt64,
// little-endian): arrays are registered with their XML attributes, their bytes are appended
// after the XML in one block, as ParaView and VTK read them.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace hoct {

class VtkAppendedData {
public:
  // Returns the <DataArray .../> element (self-closing, with its offset) for an array.
  std::string array(const std::string &name, const std::vector<double> &v, int components = 1);
  std::string array(const std::string &name, const std::vector<int64_t> &v, int components = 1);
  std::string array(const std::string &name, const std::vector<int32_t> &v, int components = 1);
  std::string array(const std::string &name, const std::vector<uint8_t> &v, int components = 1);
  // Writes <AppendedData encoding="raw">_ ...bytes... </AppendedData>.
  void write(std::ostream &out) const;

private:
  std::string add(const std::string &name, const char *type, const void *data, std::size_t bytes,
                  int components);
  std::vector<char> bytes_;
};

// Escapes &, <, >, " for use in an XML attribute.
std::string xml_escape(const std::string &s);

} // namespace hoct
