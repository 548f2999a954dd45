// Writing the DataArrays of VTK XML files (.vtu, .vtp) in every encoding VTK reads: inline
// ascii, inline base64 (optionally zlib-compressed in blocks, as vtkZLibDataCompressor writes
// them), and appended data (raw or base64). header_type is UInt64, byte order little-endian.
#pragma once

#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace hoct {

enum class VtkEncoding { Ascii, Base64, Base64Zlib, AppendedRaw, AppendedBase64 };

class VtkXmlArrays {
public:
  explicit VtkXmlArrays(VtkEncoding encoding) : encoding_(encoding) {}

  // The complete <DataArray ...>...</DataArray> element (inline) or a self-closing one with its
  // offset (appended).
  std::string array(const std::string &name, std::span<const double> v, int components = 1);
  std::string array(const std::string &name, std::span<const int64_t> v, int components = 1);
  std::string array(const std::string &name, std::span<const int32_t> v, int components = 1);
  std::string array(const std::string &name, std::span<const uint8_t> v, int components = 1);

  // Attributes for the <VTKFile> element (byte order, header type, compressor).
  std::string file_attributes() const;
  // Writes the <AppendedData> element if any array is appended (nothing otherwise).
  void write_appended(std::ostream &out) const;

private:
  template <class T>
  std::string element(const std::string &name, const char *type, std::span<const T> v,
                      int components);
  std::string encode_inline(const void *data, std::size_t bytes) const;

  VtkEncoding encoding_;
  std::string appended_; // raw bytes or base64 text
};

// Escapes &, <, >, " for use in an XML attribute.
std::string xml_escape(const std::string &s);

} // namespace hoct
