#include "io/vtk_xml_arrays.hpp"

#include "io/base64.hpp"
#include "util/error.hpp"

#include <zlib.h>

#include <cstdio>
#include <sstream>

namespace hoct {
namespace {

constexpr std::size_t kBlockSize = 32768;

template <class T> void append_ascii(std::string &out, const T &x) {
  char buf[32];
  int n;
  if constexpr (std::is_same_v<T, double>)
    n = std::snprintf(buf, sizeof buf, "%.17g", x);
  else
    n = std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(x));
  out.append(buf, static_cast<std::size_t>(n));
}

// zlib-compressed blocks with the vtkZLibDataCompressor header.
std::pair<std::vector<uint64_t>, std::string> compress_blocks(const void *data, std::size_t bytes) {
  const auto *p = static_cast<const Bytef *>(data);
  const std::size_t nblocks = bytes == 0 ? 0 : (bytes + kBlockSize - 1) / kBlockSize;
  std::vector<uint64_t> header = {
      nblocks, kBlockSize, bytes % kBlockSize == 0 ? (bytes ? kBlockSize : 0) : bytes % kBlockSize};
  std::string compressed;
  for (std::size_t b = 0; b < nblocks; ++b) {
    const std::size_t len = std::min(kBlockSize, bytes - b * kBlockSize);
    uLongf out_len = compressBound(static_cast<uLong>(len));
    std::string block(out_len, '\0');
    if (compress2(reinterpret_cast<Bytef *>(block.data()), &out_len, p + b * kBlockSize,
                  static_cast<uLong>(len), Z_DEFAULT_COMPRESSION) != Z_OK)
      throw Error("zlib compression failed");
    block.resize(out_len);
    header.push_back(out_len);
    compressed += block;
  }
  return {header, compressed};
}

} // namespace

std::string VtkXmlArrays::encode_inline(const void *data, std::size_t bytes) const {
  if (encoding_ == VtkEncoding::Base64Zlib) {
    auto [header, compressed] = compress_blocks(data, bytes);
    return base64_encode(header.data(), header.size() * sizeof(uint64_t)) +
           base64_encode(compressed.data(), compressed.size());
  }
  const uint64_t n = bytes;
  return base64_encode(&n, sizeof n) + base64_encode(data, bytes);
}

template <class T>
std::string VtkXmlArrays::element(const std::string &name, const char *type, std::span<const T> v,
                                  int components) {
  std::string e = "<DataArray type=\"" + std::string(type) + "\" Name=\"" + xml_escape(name) +
                  "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"";
  const std::size_t bytes = v.size() * sizeof(T);
  switch (encoding_) {
  case VtkEncoding::Ascii: {
    e += "ascii\">";
    for (std::size_t i = 0; i < v.size(); ++i) {
      e += (i % 9 == 0) ? "\n" : " ";
      append_ascii(e, v[i]);
    }
    e += "\n</DataArray>";
    return e;
  }
  case VtkEncoding::Base64:
  case VtkEncoding::Base64Zlib:
    e += "binary\">\n" + encode_inline(v.data(), bytes) + "\n</DataArray>";
    return e;
  case VtkEncoding::AppendedRaw: {
    e += "appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>";
    const uint64_t n = bytes;
    appended_.append(reinterpret_cast<const char *>(&n), sizeof n);
    appended_.append(reinterpret_cast<const char *>(v.data()), bytes);
    return e;
  }
  case VtkEncoding::AppendedBase64: {
    e += "appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>";
    const uint64_t n = bytes;
    appended_ += base64_encode(&n, sizeof n) + base64_encode(v.data(), bytes);
    return e;
  }
  }
  return e;
}

std::string VtkXmlArrays::array(const std::string &name, std::span<const double> v, int c) {
  return element(name, "Float64", v, c);
}
std::string VtkXmlArrays::array(const std::string &name, std::span<const int64_t> v, int c) {
  return element(name, "Int64", v, c);
}
std::string VtkXmlArrays::array(const std::string &name, std::span<const int32_t> v, int c) {
  return element(name, "Int32", v, c);
}
std::string VtkXmlArrays::array(const std::string &name, std::span<const uint8_t> v, int c) {
  return element(name, "UInt8", v, c);
}

std::string VtkXmlArrays::file_attributes() const {
  std::string a = "version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  if (encoding_ == VtkEncoding::Base64Zlib)
    a += " compressor=\"vtkZLibDataCompressor\"";
  return a;
}

void VtkXmlArrays::write_appended(std::ostream &out) const {
  if (encoding_ == VtkEncoding::AppendedRaw) {
    out << "  <AppendedData encoding=\"raw\">\n   _";
    out.write(appended_.data(), static_cast<std::streamsize>(appended_.size()));
    out << "\n  </AppendedData>\n";
  } else if (encoding_ == VtkEncoding::AppendedBase64) {
    out << "  <AppendedData encoding=\"base64\">\n   _" << appended_ << "\n  </AppendedData>\n";
  }
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
