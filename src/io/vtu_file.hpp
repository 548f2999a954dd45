// The reader of VTK XML UnstructuredGrid files (io/vtu_reader.hpp), shared by the whole-file read
// (io/vtu_reader.cpp) and the read of a range of cells (io/vtu_cell_range.cpp). Internal to io/.
#pragma once

#include "io/field_selection.hpp"
#include "io/file_bytes.hpp"
#include "io/vtu_cell_range.hpp"
#include "io/vtu_reader.hpp"
#include "util/page_pool.hpp"

#include <pugixml.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hoct::vtu_detail {

// The largest expansion zlib's deflate format allows (about 1032:1), with margin.
inline constexpr uint64_t kMaxZlibRatio = 1100;

// Large reads go in parts of this size (on the reader's threads).
inline constexpr std::size_t kReadPart = std::size_t{4} << 20;

enum class Scalar { F32, F64, I8, U8, I16, U16, I32, U32, I64, U64 };

struct TypeInfo {
  const char *name;
  Scalar type;
  int size;
};
inline constexpr TypeInfo kTypes[] = {
    {"Float32", Scalar::F32, 4}, {"Float64", Scalar::F64, 8}, {"Int8", Scalar::I8, 1},
    {"UInt8", Scalar::U8, 1},    {"Int16", Scalar::I16, 2},   {"UInt16", Scalar::U16, 2},
    {"Int32", Scalar::I32, 4},   {"UInt32", Scalar::U32, 4},  {"Int64", Scalar::I64, 8},
    {"UInt64", Scalar::U64, 8},  {"Float", Scalar::F32, 4},   {"Double", Scalar::F64, 8}};

// A binary array's bytes: in the file's buffer (raw appended data, read in place) or decoded
// into a buffer of its own (base64, zlib).
struct Payload {
  std::vector<uint8_t> owned;
  const uint8_t *data = nullptr;
  std::size_t size = 0;
};

class VtuFile {
public:
  VtuFile(std::string path, FieldSelection field, const ReadLimits &limits,
          VtuPieceRequest request = {})
      : path_(std::move(path)), field_(std::move(field)), limits_(limits),
        request_(std::move(request)) {}
  VtuFile(const VtuFile &) = delete;
  VtuFile &operator=(const VtuFile &) = delete;
  ~VtuFile() {
    if (fd_ >= 0)
      ::close(fd_);
  }
  // Reads the file at path_: into bytes_, or (large, raw appended payload) only the XML around
  // the payload, whose arrays are then read from the file as they are needed.
  void read_file();
  void set_bytes(std::string bytes) {
    bytes_ = FileBytes(std::move(bytes));
    file_size_ = bytes_.size();
  }
  MeshInput read();
  // Part `part` of `parts` of the file's one piece (io/vtu_cell_range.hpp); the file opened
  // with open_for_ranges. Empty, with `why`, for a file that cannot be read by parts.
  std::optional<VtuCellRange> read_cell_range(int part, int parts, std::string &why);
  // Opens the file for reading arrays by ranges: false (nothing read) unless its payload is
  // raw appended data.
  bool open_for_ranges();
  // The bookkeeping arrays read() found (ghost levels, global ids).
  VtuPieceArrays &arrays() { return arrays_; }

private:
  [[noreturn]] void fail(const std::string &what) const { throw InputError(path_ + ": " + what); }
  // "line N" of element n in the file (from its offset in the parsed text).
  std::string line_of(const pugi::xml_node &n) const;
  // What XML parsers may let pass and VTK's files never have: a second root element, an
  // attribute given twice (not well-formed XML; pugixml keeps both and the first would win), a
  // second <UnstructuredGrid>, or a second <Points>, <PointData> or <Cells> in a piece.
  void check_structure() const;
  // The only child `name` of parent (null if none); a second one is refused.
  pugi::xml_node single_child(const pugi::xml_node &parent, const char *name) const;
  // The DataArray of parent named `name` (null if none); a second one of that name is refused.
  pugi::xml_node named_array(const pugi::xml_node &parent, const std::string &name) const;
  // The point-data array field_ names in pd, or the default (FieldSelection::name); refuses
  // what cannot give a scalar field, listing the arrays there are.
  pugi::xml_node choose_field(const pugi::xml_node &pd, const std::string &where) const;
  // A piece's <Points> DataArray and its component count (2 or 3), refused otherwise.
  pugi::xml_node points_array(const pugi::xml_node &piece, const std::string &where,
                              int &components) const;
  // A piece's <Cells> arrays: connectivity, offsets, types (each required).
  std::array<pugi::xml_node, 3> cell_arrays(const pugi::xml_node &piece,
                                            const std::string &where) const;
  void load();
  void load_whole();
  bool open_streamed();
  void read_at(uint64_t at, std::size_t n, void *dst) const;
  template <class V> void resize_mapped(V &v, std::size_t n) const;
  uint64_t appended_offset(const pugi::xml_node &a, std::size_t appended_size) const;
  Payload payload_from_file(uint64_t at, uint64_t avail, const pugi::xml_node &a,
                            uint64_t expected_bytes) const;
  uint64_t raw_array_bytes(uint64_t at, uint64_t avail, const pugi::xml_node &a) const;
  std::size_t value_count(const pugi::xml_node &a, const TypeInfo &ti, uint64_t bytes,
                          std::size_t expected) const;
  const TypeInfo &type_of(const pugi::xml_node &a) const;
  std::string describe(const pugi::xml_node &a) const;
  // The bytes of binary array a, which must hold `expected_bytes` (the header counts times the
  // type's size): a compressed array's declared size is checked against it before inflating.
  Payload binary_payload(const pugi::xml_node &a, uint64_t expected_bytes) const;
  Payload decode_blocks(const uint8_t *p, std::size_t avail, const pugi::xml_node &a,
                        uint64_t expected_bytes) const;
  Payload decode_owned(std::vector<uint8_t> buffer, const pugi::xml_node &a,
                       uint64_t expected_bytes) const;
  template <class S, class T>
  void convert_binary(const Payload &raw, const pugi::xml_node &a, PooledVector<T> &out) const;
  // Copies a binary array stored as `type` in the machine's byte order straight into dst (room
  // for `expected` values of it); false, with nothing read, for any other array.
  bool read_native(const pugi::xml_node &a, Scalar type, void *dst, std::size_t expected) const;
  PooledVector<double> read_doubles(const pugi::xml_node &a, std::size_t expected) const;
  PooledVector<int64_t> read_ints(const pugi::xml_node &a, std::size_t expected) const;
  template <class T>
  PooledVector<T> read_array(const pugi::xml_node &a, std::size_t expected) const;
  // The values of binary array a as T, converted from the type it is stored as.
  template <class T>
  void convert_payload(const Payload &raw, const pugi::xml_node &a, PooledVector<T> &out) const;
  // Values [first, first + count) of appended array a of `expected` values in all, as T (a
  // streamed file: read_cell_range); a compressed array's blocks over the range alone.
  template <class T>
  PooledVector<T> read_array_range(const pugi::xml_node &a, std::size_t expected, std::size_t first,
                                   std::size_t count) const;
  // The same into dst (room for `count`): an array stored as T in the machine's byte order,
  // uncompressed, straight from the file.
  template <class T>
  void read_range_into(const pugi::xml_node &a, std::size_t expected, std::size_t first,
                       std::size_t count, T *dst) const;
  // A piece's vtkGhostType array in `data` (PointData or CellData), `n` flags (empty if none).
  // Bezier cells (from cell `first_cell` on) of a piece whose PointData has RationalWeights:
  // refused unless every weight they use is 1 (rational cells are not polynomials).
  void check_rational_weights(const MeshInput &m, std::size_t first_cell, const pugi::xml_node &pd,
                              std::size_t np, int64_t base, const std::string &where) const;
  std::vector<uint8_t> read_ghost(const pugi::xml_node &data, std::size_t n,
                                  const std::string &where) const;
  // The bookkeeping arrays of a piece of np points whose first point is `base`.
  void read_point_arrays(const pugi::xml_node &pd, int64_t base, std::size_t np,
                         const std::string &where);

  std::string path_;
  FieldSelection field_;
  ReadLimits limits_;
  VtuPieceRequest request_;
  VtuPieceArrays arrays_;
  bool ids_incomplete_ = false; // a piece of the file has no global ids
  FileBytes bytes_;             // the file (unless streamed)
  uint64_t file_size_ = 0;
  int fd_ = -1;                  // the open file, when streamed
  bool streamed_ = false;        // the appended payload stays in the file:
  uint64_t appended_begin_ = 0;  //   its first byte (after '_')
  uint64_t appended_length_ = 0; //   and its length
  std::string xml_;              // the file without the appended payload
  std::string_view appended_;    // appended payload (after '_')
  bool appended_base64_ = false;
  pugi::xml_document doc_;
  const char *xml_text_ = nullptr; // the text doc_ was parsed from (in place)
  int header_size_ = 4;
  bool big_endian_ = false, compressed_ = false;
};

uint64_t read_uint(const uint8_t *p, int size, bool big);
// Count of values of a DataArray whose length is known only from its own data (offsets).
long long parse_count(const pugi::xml_attribute &a);

} // namespace hoct::vtu_detail
