#include "io/vtu_reader.hpp"

#include "io/vtu_file.hpp"

#include "io/external_reader.hpp"

#include "io/base64.hpp"
#include "io/file_bytes.hpp"
#include "io/pvtu_reader.hpp"
#include "io/vtk_cells.hpp"
#include "io/xml_structure.hpp"
#include "util/error.hpp"
#include "util/page_pool.hpp"
#include "util/parallel_for.hpp"

#include <pugixml.hpp>
#include <zlib.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace hoct {
namespace vtu_detail {

void VtuFile::read_file() {
  if (open_streamed())
    return;
  std::string error;
  if (!bytes_.read(path_, error))
    fail(error == "is a directory" ? std::string("is a directory, not a .vtu file") : error);
  file_size_ = bytes_.size();
}

// A large file with a raw appended payload: reads the XML before the payload (in chunks, until
// the '_' that starts it) and after it (the end of the file), and keeps the file open. False,
// with nothing kept, for any other file: read whole, it gets the usual checks and messages.
bool VtuFile::open_streamed() {
  const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    return false;
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) ||
      static_cast<uint64_t>(st.st_size) <= limits_.stream_appended_above) {
    ::close(fd);
    return false;
  }
  fd_ = fd;
  const uint64_t size = static_cast<uint64_t>(st.st_size);
  constexpr std::size_t kChunk = std::size_t{1} << 20, kMaxHead = std::size_t{64} << 20;
  std::string head;
  std::size_t tag = std::string::npos, close = std::string::npos, underscore = std::string::npos;
  while (head.size() < std::min<uint64_t>(size, kMaxHead)) {
    const std::size_t at = head.size();
    const std::size_t n = static_cast<std::size_t>(std::min<uint64_t>(kChunk, size - at));
    head.resize(at + n);
    const ssize_t r = ::pread(fd_, head.data() + at, n, static_cast<off_t>(at));
    if (r <= 0)
      break;
    head.resize(at + static_cast<std::size_t>(r));
    if (tag == std::string::npos)
      tag = head.find("<AppendedData", at >= 13 ? at - 13 : 0);
    if (tag != std::string::npos && close == std::string::npos)
      close = head.find('>', tag);
    if (close != std::string::npos)
      underscore = head.find('_', close);
    if (underscore != std::string::npos)
      break;
  }
  const std::size_t tail_size = static_cast<std::size_t>(std::min<uint64_t>(size, kChunk));
  std::string tail(tail_size, '\0');
  const bool have_tail =
      underscore != std::string::npos &&
      ::pread(fd_, tail.data(), tail_size, static_cast<off_t>(size - tail_size)) ==
          static_cast<ssize_t>(tail_size);
  const std::size_t end = have_tail ? tail.rfind("</AppendedData>") : std::string::npos;
  const uint64_t end_at = size - tail_size + end; // file offset of "</AppendedData>"
  if (end == std::string::npos || end_at <= underscore ||
      std::string_view(head).substr(tag, close - tag).find("\"raw\"") == std::string::npos) {
    ::close(fd_);
    fd_ = -1;
    return false;
  }
  head.resize(close + 1);
  xml_ = std::move(head);
  xml_.append(tail, end, std::string::npos);
  appended_begin_ = underscore + 1;
  appended_length_ = end_at - appended_begin_;
  file_size_ = size;
  streamed_ = true;
  return true;
}

// v resized to n elements (zeroed), its new pages mapped first in parts on the reader's threads
// (one call per part instead of a fault per page: the zeroing alone would fault the pages of the
// largest arrays in one page at a time on one thread, a large part of reading a large file).
// For arrays about to be filled from the file.
template <class V> void VtuFile::resize_mapped(V &v, std::size_t n) const {
  const std::size_t old = v.size();
  if (n <= old) {
    v.resize(n);
    return;
  }
  // Geometric growth over a file's pieces (one exact allocation for one piece).
  if (n > v.capacity())
    v.reserve(std::max(n, 2 * v.capacity()));
  char *begin = reinterpret_cast<char *>(v.data() + old);
  const std::size_t bytes = (n - old) * sizeof(typename V::value_type);
  if (bytes >= 2 * kReadPart) {
    const int64_t parts = static_cast<int64_t>((bytes + kReadPart - 1) / kReadPart);
    parallel_chunks(parts, parts, thread_count(limits_.threads),
                    [&](int64_t part, int64_t, int64_t, int) {
                      const std::size_t at = static_cast<std::size_t>(part) * kReadPart;
                      populate_for_write(begin + at, std::min(bytes, at + kReadPart) - at);
                    });
  }
  v.resize(n);
}

// n bytes of the file from offset `at` into dst (its pages already mapped: resize_mapped, or a
// zeroed buffer). Large reads go in parts of kReadPart bytes on the reader's threads.
void VtuFile::read_at(uint64_t at, std::size_t n, void *dst) const {
  auto read_part = [&](std::size_t begin, std::size_t end) {
    char *d = static_cast<char *>(dst);
    std::size_t got = begin;
    while (got < end) {
      const ssize_t r = ::pread(fd_, d + got, end - got, static_cast<off_t>(at + got));
      if (r < 0 && errno == EINTR)
        continue;
      if (r <= 0)
        fail(r < 0
                 ? "cannot read (" + std::string(std::strerror(errno)) + ")"
                 : std::string("cannot read: the file ends early (it changed while it was read)"));
      got += static_cast<std::size_t>(r);
    }
  };
  if (n < 2 * kReadPart) {
    read_part(0, n);
    return;
  }
  const int64_t parts = static_cast<int64_t>((n + kReadPart - 1) / kReadPart);
  parallel_chunks(parts, parts, thread_count(limits_.threads),
                  [&](int64_t part, int64_t, int64_t, int) {
                    const std::size_t begin = static_cast<std::size_t>(part) * kReadPart;
                    read_part(begin, std::min(n, begin + kReadPart));
                  });
}

// The XML of a file read whole, its appended payload (if any) cut out first.
void VtuFile::load_whole() {
  if (bytes_.empty())
    fail("the file is empty");
  // Cut the appended payload out before XML parsing: raw bytes may contain anything.
  const std::string_view bytes = bytes_.view();
  const std::size_t tag = bytes.find("<AppendedData");
  // Parsed in place (pugixml writes into the text it parses): the whole file, unless the
  // payload is cut out below.
  char *xml = bytes_.data();
  std::size_t xml_size = bytes_.size();
  if (tag != std::string::npos) {
    const std::size_t close = bytes.find('>', tag);
    const std::size_t underscore = close == std::string::npos ? close : bytes.find('_', close);
    const std::size_t end = bytes.rfind("</AppendedData>");
    if (close == std::string::npos || underscore == std::string::npos || end == std::string::npos ||
        end < underscore)
      fail("truncated or malformed <AppendedData> section (missing '_' marker or "
           "</AppendedData>)");
    const std::string_view head = bytes.substr(tag, close - tag);
    appended_base64_ = head.find("\"base64\"") != std::string::npos;
    if (!appended_base64_ && head.find("\"raw\"") == std::string::npos)
      fail("<AppendedData> has an unknown encoding (expected raw or base64)");
    appended_ = bytes.substr(underscore + 1, end - underscore - 1);
    xml_.reserve(close + 1 + (bytes.size() - end));
    xml_.append(bytes.substr(0, close + 1)).append(bytes.substr(end));
    xml = xml_.data();
    xml_size = xml_.size();
  }
  xml_text_ = xml;
  const pugi::xml_parse_result r = doc_.load_buffer_inplace(xml, xml_size);
  if (!r)
    fail(std::string("not valid XML: ") + r.description() + " at byte " + std::to_string(r.offset));
}

std::string VtuFile::line_of(const pugi::xml_node &n) const {
  const std::ptrdiff_t at = n.offset_debug();
  if (at < 0 || xml_text_ == nullptr)
    return "<" + std::string(n.name()) + ">";
  return "<" + std::string(n.name()) + "> at line " +
         std::to_string(1 + std::count(xml_text_, xml_text_ + at, '\n'));
}

void VtuFile::check_structure() const {
  const std::string problem =
      xml_structure_problem(doc_, [this](const pugi::xml_node &e) { return line_of(e); });
  if (!problem.empty())
    fail(problem);
}

pugi::xml_node VtuFile::single_child(const pugi::xml_node &parent, const char *name) const {
  const pugi::xml_node c = parent.child(name);
  if (c)
    for (pugi::xml_node d = c.next_sibling(name); d; d = d.next_sibling(name))
      fail("a second " + line_of(d) + " in " + line_of(parent) + " (the first is " + line_of(c) +
           "): which one holds the data is ambiguous");
  return c;
}

pugi::xml_node VtuFile::named_array(const pugi::xml_node &parent, const std::string &name) const {
  pugi::xml_node found;
  for (auto a : parent.children("DataArray")) {
    if (a.attribute("Name").as_string() != name)
      continue;
    if (found)
      fail("two DataArrays named '" + name + "' in " + line_of(parent) + " (" + line_of(found) +
           " and " + line_of(a) + "): which one to read is ambiguous");
    found = a;
  }
  return found;
}

pugi::xml_node VtuFile::choose_field(const pugi::xml_node &pd, const std::string &where) const {
  const bool vector = field_.component != FieldSelection::kScalar;
  auto components = [](const pugi::xml_node &a) {
    return a.attribute("NumberOfComponents").as_int(1);
  };
  auto floating = [](const pugi::xml_node &a) {
    const std::string t = a.attribute("type").as_string();
    return t == "Float32" || t == "Float64" || t == "Float" || t == "Double";
  };
  auto suitable = [&](const pugi::xml_node &a) {
    return vector ? components(a) > 1 : components(a) == 1;
  };
  std::string available;
  for (auto a : pd.children("DataArray")) {
    const int comps = components(a);
    available += (available.empty() ? "" : ", ") + std::string(a.attribute("Name").as_string()) +
                 (comps != 1 ? " (" + std::to_string(comps) + " components)" : "");
  }
  const std::string listed = available.empty() ? std::string(" (the file has no point data)")
                                               : " (available: " + available + ")";
  pugi::xml_node sa;
  if (!field_.name.empty()) {
    sa = named_array(pd, field_.name);
    if (!sa)
      fail(where + ": no point-data array named '" + field_.name + "'" + listed);
  } else {
    // The active scalars (or vectors) first, then the first floating-point array that is no
    // id, ghost or mask array, then the first integer one of those.
    const std::string active = pd.attribute(vector ? "Vectors" : "Scalars").as_string();
    if (!active.empty()) {
      const pugi::xml_node a = named_array(pd, active);
      if (a && suitable(a) && !is_bookkeeping_array(active))
        sa = a;
    }
    for (int pass = 0; pass < 2 && !sa; ++pass)
      for (auto a : pd.children("DataArray"))
        if (suitable(a) && (pass == 1 || floating(a)) &&
            !is_bookkeeping_array(a.attribute("Name").as_string())) {
          sa = a;
          break;
        }
    if (!sa)
      fail(where + ": no " +
           (vector ? std::string("vector") : std::string("scalar (one-component)")) +
           " point-data array but ids, ghost levels or masks" + listed +
           (available.empty() ? "" : ": name one with --scalar"));
    named_array(pd, sa.attribute("Name").as_string()); // refuses a second of that name
  }
  const int comps = components(sa);
  const std::string name = sa.attribute("Name").as_string();
  if (comps < 1 || comps > 64)
    fail(where + ": point-data array '" + name + "' has " + std::to_string(comps) + " components");
  if (!vector && comps != 1)
    fail(where + ": point-data array '" + name + "' has " + std::to_string(comps) +
         " components; a scalar field needs 1 (choose one with --component N, or --component "
         "magnitude)");
  if (vector && comps == 1)
    fail(where + ": --component: point-data array '" + name + "' has one component");
  if (field_.component >= comps)
    fail(where + ": --component " + std::to_string(field_.component) + ": point-data array '" +
         name + "' has " + std::to_string(comps) + " components (0 to " +
         std::to_string(comps - 1) + ")");
  return sa;
}

void VtuFile::load() {
  if (streamed_) { // the XML around the payload is in xml_ already
    xml_text_ = xml_.data();
    const pugi::xml_parse_result r = doc_.load_buffer_inplace(xml_.data(), xml_.size());
    if (!r)
      fail(std::string("not valid XML: ") + r.description() + " at byte " +
           std::to_string(r.offset));
  } else {
    load_whole();
  }
  check_structure();
  const pugi::xml_node root = doc_.child("VTKFile");
  if (!root)
    fail("not a VTK XML file (no <VTKFile> element)");
  const std::string type = root.attribute("type").as_string();
  if (type != "UnstructuredGrid")
    fail("VTK file type is '" + type + "', expected UnstructuredGrid (.vtu)");
  const std::string order = root.attribute("byte_order").as_string("LittleEndian");
  if (order != "LittleEndian" && order != "BigEndian")
    fail("unknown byte_order '" + order + "'");
  big_endian_ = order == "BigEndian";
  const std::string header = root.attribute("header_type").as_string("UInt32");
  if (header == "UInt32")
    header_size_ = 4;
  else if (header == "UInt64")
    header_size_ = 8;
  else
    fail("unsupported header_type '" + header + "' (UInt32 or UInt64)");
  const std::string comp = root.attribute("compressor").as_string();
  if (comp == "vtkZLibDataCompressor")
    compressed_ = true;
  else if (!comp.empty())
    throw VtuCompressorError(path_ + ": unsupported compressor '" + comp +
                             "' (hoct's reader reads vtkZLibDataCompressor; this hoct was built "
                             "without VTK, whose reader reads the others)");
}

const TypeInfo &VtuFile::type_of(const pugi::xml_node &a) const {
  const std::string t = a.attribute("type").as_string();
  for (const auto &ti : kTypes)
    if (t == ti.name)
      return ti;
  fail(describe(a) + " has unsupported type '" + t + "'");
}

std::string VtuFile::describe(const pugi::xml_node &a) const {
  const std::string name = a.attribute("Name").as_string();
  return "DataArray" + (name.empty() ? std::string() : " '" + name + "'") + " in <" +
         a.parent().name() + ">";
}

uint64_t read_uint(const uint8_t *p, int size, bool big) {
  uint64_t v = 0;
  for (int i = 0; i < size; ++i)
    v |= uint64_t{p[big ? size - 1 - i : i]} << (8 * i);
  return v;
}

// Decodes a (possibly compressed) binary array starting at p: the header, then the data.
Payload VtuFile::decode_blocks(const uint8_t *p, std::size_t avail, const pugi::xml_node &a,
                               uint64_t expected_bytes) const {
  const int hs = header_size_;
  auto need = [&](std::size_t n, const char *what) {
    if (n > avail)
      fail(describe(a) + ": truncated binary data (" + what + " needs " + std::to_string(n) +
           " bytes, " + std::to_string(avail) + " available)");
  };
  if (!compressed_) {
    need(hs, "the header");
    const uint64_t n = read_uint(p, hs, big_endian_);
    if (n > avail - hs) // not need(hs + n): a hostile n makes the sum wrap around
      fail(describe(a) + ": truncated binary data (the header claims " + std::to_string(n) +
           " bytes, " + std::to_string(avail - hs) + " available)");
    return Payload{{}, p + hs, static_cast<std::size_t>(n)}; // read in place
  }
  need(3 * hs, "the compression header");
  const uint64_t nb = read_uint(p, hs, big_endian_), bs = read_uint(p + hs, hs, big_endian_),
                 last = read_uint(p + 2 * hs, hs, big_endian_);
  if (nb > avail / hs)
    fail(describe(a) + ": compression header claims " + std::to_string(nb) + " blocks");
  need((3 + nb) * hs, "the compression header");
  std::size_t total = 0, pos = (3 + nb) * hs;
  std::vector<uint64_t> csize(nb);
  for (uint64_t b = 0; b < nb; ++b) {
    csize[b] = read_uint(p + (3 + b) * hs, hs, big_endian_);
    total += csize[b];
    if (csize[b] > avail)
      fail(describe(a) + ": compressed block " + std::to_string(b) + " claims " +
           std::to_string(csize[b]) + " bytes");
  }
  need(pos + total, "the compressed blocks");
  if (bs > (uint64_t{1} << 31) || last > bs)
    fail(describe(a) + ": implausible compression header (block size " + std::to_string(bs) +
         ", last block " + std::to_string(last) + ")");
  // zlib expands at most ~1032:1, so a block's size is bounded by its compressed size: check
  // every block before allocating for any (a hostile header cannot make us allocate gigabytes).
  uint64_t out_size = 0;
  for (uint64_t b = 0; b < nb; ++b) {
    const uint64_t want = (b + 1 == nb && last) ? last : bs;
    if (want > kMaxZlibRatio * csize[b] + 64)
      fail(describe(a) + ": compressed block " + std::to_string(b) + " of " +
           std::to_string(csize[b]) + " bytes cannot expand to the " + std::to_string(want) +
           " bytes the header claims");
    out_size += want;
  }
  // A zlib bomb (blocks that inflate to gigabytes) is refused here, before anything inflates:
  // the declared size must be the array's expected size (the header counts times the type's
  // size), which the memory budget has already been checked against (check_memory, whose
  // estimate includes every array's bytes), so what inflates stays within the budget.
  if (out_size != expected_bytes) {
    const TypeInfo &ti = type_of(a);
    fail(describe(a) + " has " +
         (out_size % ti.size ? std::to_string(out_size) + " bytes"
                             : std::to_string(out_size / ti.size) + " values") +
         " (as its compression header declares, before inflating), expected " +
         std::to_string(expected_bytes / ti.size) + " " + ti.name + " values");
  }
  Payload r;
  std::vector<uint8_t> &out = r.owned;
  out.resize(out_size);
  std::size_t at = 0;
  for (uint64_t b = 0; b < nb; ++b) {
    const uint64_t want = (b + 1 == nb && last) ? last : bs;
    uLongf got = static_cast<uLongf>(want);
    const int rc = uncompress(out.data() + at, &got, p + pos, static_cast<uLong>(csize[b]));
    if (rc != Z_OK || got != want)
      fail(describe(a) + ": zlib error in block " + std::to_string(b) + " (" +
           (rc == Z_OK ? "wrong size" : zError(rc)) + ")");
    pos += csize[b];
    at += want;
  }
  r.data = out.data();
  r.size = out.size();
  return r;
}

// decode_blocks on a buffer of our own (decoded base64), which the result then keeps when it
// points into it.
Payload VtuFile::decode_owned(std::vector<uint8_t> buffer, const pugi::xml_node &a,
                              uint64_t expected_bytes) const {
  Payload r = decode_blocks(buffer.data(), buffer.size(), a, expected_bytes);
  if (r.owned.empty()) {
    const std::size_t at = r.size == 0 ? 0 : static_cast<std::size_t>(r.data - buffer.data());
    r.owned = std::move(buffer);
    r.data = r.owned.data() + at;
  }
  return r;
}

// The offset attribute of an appended array, checked against the payload's size.
uint64_t VtuFile::appended_offset(const pugi::xml_node &a, std::size_t appended_size) const {
  const auto offset_attr = a.attribute("offset");
  if (!offset_attr)
    fail(describe(a) + " is appended but has no offset");
  const long long offset = offset_attr.as_llong(-1);
  if (offset < 0 || static_cast<uint64_t>(offset) > appended_size)
    fail(describe(a) + ": offset " + offset_attr.as_string() + " is outside the appended data (" +
         std::to_string(appended_size) + " bytes)");
  return static_cast<uint64_t>(offset);
}

// The byte count in the header of a streamed file's uncompressed array at file offset `at`
// (its data follows the header), checked against the `avail` bytes of payload from there.
uint64_t VtuFile::raw_array_bytes(uint64_t at, uint64_t avail, const pugi::xml_node &a) const {
  const int hs = header_size_;
  if (avail < static_cast<uint64_t>(hs))
    fail(describe(a) + ": truncated binary data (the header needs " + std::to_string(hs) +
         " bytes, " + std::to_string(avail) + " available)");
  uint8_t h[8];
  read_at(at, hs, h);
  const uint64_t n = read_uint(h, hs, big_endian_);
  if (n > avail - hs)
    fail(describe(a) + ": truncated binary data (the header claims " + std::to_string(n) +
         " bytes, " + std::to_string(avail - hs) + " available)");
  return n;
}

// The number of values of type ti in `bytes` bytes of a binary array, which must be whole and
// `expected`.
std::size_t VtuFile::value_count(const pugi::xml_node &a, const TypeInfo &ti, uint64_t bytes,
                                 std::size_t expected) const {
  if (bytes % ti.size != 0)
    fail(describe(a) + ": " + std::to_string(bytes) + " bytes is not a whole number of " + ti.name +
         " values");
  if (bytes / ti.size != expected)
    fail(describe(a) + " has " + std::to_string(bytes / ti.size) + " values, expected " +
         std::to_string(expected));
  return expected;
}

// A streamed file's raw appended array at file offset `at`, with `avail` bytes of payload from
// there: its headers are read and checked first (as decode_blocks checks them), so that no
// claimed size makes us read or allocate beyond the payload; then the array's bytes.
Payload VtuFile::payload_from_file(uint64_t at, uint64_t avail, const pugi::xml_node &a,
                                   uint64_t expected_bytes) const {
  const int hs = header_size_;
  auto truncated = [&](const char *what, uint64_t n) {
    fail(describe(a) + ": truncated binary data (" + what + " needs " + std::to_string(n) +
         " bytes, " + std::to_string(avail) + " available)");
  };
  uint8_t h[3 * 8];
  if (!compressed_) {
    const uint64_t n = raw_array_bytes(at, avail, a);
    Payload r;
    r.owned.resize(static_cast<std::size_t>(n));
    read_at(at + hs, r.owned.size(), r.owned.data());
    r.data = r.owned.data();
    r.size = r.owned.size();
    return r;
  }
  if (avail < 3 * static_cast<uint64_t>(hs))
    truncated("the compression header", 3 * hs);
  read_at(at, 3 * hs, h);
  const uint64_t nb = read_uint(h, hs, big_endian_);
  if (nb > avail / hs)
    fail(describe(a) + ": compression header claims " + std::to_string(nb) + " blocks");
  if ((3 + nb) * hs > avail)
    truncated("the compression header", (3 + nb) * hs);
  std::vector<uint8_t> all(static_cast<std::size_t>((3 + nb) * hs));
  read_at(at, all.size(), all.data());
  uint64_t total = 0;
  for (uint64_t b = 0; b < nb; ++b) {
    const uint64_t csize = read_uint(all.data() + (3 + b) * hs, hs, big_endian_);
    if (csize > avail)
      fail(describe(a) + ": compressed block " + std::to_string(b) + " claims " +
           std::to_string(csize) + " bytes");
    total += csize;
  }
  if (all.size() + total > avail)
    truncated("the compressed blocks", all.size() + total);
  const std::size_t header_bytes = all.size();
  all.resize(header_bytes + static_cast<std::size_t>(total));
  read_at(at + header_bytes, static_cast<std::size_t>(total), all.data() + header_bytes);
  return decode_owned(std::move(all), a, expected_bytes);
}

Payload VtuFile::binary_payload(const pugi::xml_node &a, uint64_t expected_bytes) const {
  const std::string format = a.attribute("format").as_string();
  if (format == "binary") {
    std::vector<uint8_t> raw;
    try {
      raw = base64_decode(a.child_value());
    } catch (const std::invalid_argument &e) {
      fail(describe(a) + ": bad base64 data (" + e.what() + ")");
    }
    return decode_owned(std::move(raw), a, expected_bytes);
  }
  // appended
  if (streamed_) {
    const uint64_t offset = appended_offset(a, appended_length_);
    return payload_from_file(appended_begin_ + offset, appended_length_ - offset, a,
                             expected_bytes);
  }
  if (appended_.data() == nullptr)
    fail(describe(a) + " is appended but the file has no <AppendedData> section");
  const std::string_view rest = appended_.substr(appended_offset(a, appended_.size()));
  if (!appended_base64_)
    return decode_blocks(reinterpret_cast<const uint8_t *>(rest.data()), rest.size(), a,
                         expected_bytes);
  // Appended base64: decode just this array's streams. The header is its own stream (VTK) or
  // shares one with the data; the padding of the first group tells which.
  try {
    const int hs = header_size_;
    auto decode = [&](std::size_t chars) {
      if (chars > rest.size())
        fail(describe(a) + ": truncated appended base64 data");
      return base64_decode(rest.substr(0, chars));
    };
    if (!compressed_) {
      const std::size_t hchars = base64_length(hs);
      const std::vector<uint8_t> h = decode(hchars);
      if (h.size() < static_cast<std::size_t>(hs))
        fail(describe(a) + ": truncated appended base64 header");
      const uint64_t n = read_uint(h.data(), hs, big_endian_);
      if (n > rest.size())
        fail(describe(a) + ": header claims " + std::to_string(n) + " bytes");
      const bool separate = rest.substr(0, hchars).find('=') != std::string_view::npos;
      const std::size_t chars = separate ? hchars + base64_length(n) : base64_length(hs + n);
      std::vector<uint8_t> all = decode(chars);
      return decode_owned(std::move(all), a, expected_bytes);
    }
    const std::vector<uint8_t> h3 = decode(base64_length(3 * hs));
    if (h3.size() < 3 * static_cast<std::size_t>(hs))
      fail(describe(a) + ": truncated appended base64 compression header");
    const uint64_t nb = read_uint(h3.data(), hs, big_endian_);
    if (nb > rest.size())
      fail(describe(a) + ": compression header claims " + std::to_string(nb) + " blocks");
    const std::size_t hchars = base64_length((3 + nb) * hs);
    const std::vector<uint8_t> h = decode(hchars);
    if (h.size() < (3 + nb) * hs)
      fail(describe(a) + ": truncated appended base64 compression header");
    uint64_t total = 0;
    for (uint64_t b = 0; b < nb && total <= rest.size(); ++b)
      total +=
          std::min<uint64_t>(read_uint(h.data() + (3 + b) * hs, hs, big_endian_), rest.size() + 1);
    if (total > rest.size())
      fail(describe(a) + ": compressed sizes exceed the appended data");
    std::vector<uint8_t> all = decode(hchars + base64_length(total));
    return decode_owned(std::move(all), a, expected_bytes);
  } catch (const std::invalid_argument &e) {
    fail(describe(a) + ": bad base64 data (" + e.what() + ")");
  }
}

// The values of a binary array stored as S (in the file's byte order), as T: one copy when S is T
// in the machine's order, else value by value. Floating-point values read as integers must be
// integral, and unsigned 64-bit ones must fit a signed one.
template <class S, class T>
void VtuFile::convert_binary(const Payload &raw, const pugi::xml_node &a,
                             PooledVector<T> &out) const {
  const std::size_t n = raw.size / sizeof(S);
  out.resize(n);
  const bool swap = big_endian_ != (std::endian::native == std::endian::big);
  if constexpr (std::is_same_v<S, T>) {
    if (!swap) {
      if (n > 0)
        std::memcpy(out.data(), raw.data, n * sizeof(S));
      return;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    uint8_t b[sizeof(S)];
    std::memcpy(b, raw.data + i * sizeof(S), sizeof(S));
    if (swap)
      std::reverse(b, b + sizeof(S));
    S v;
    std::memcpy(&v, b, sizeof(S));
    if constexpr (std::is_same_v<S, uint64_t>) {
      if (v > static_cast<uint64_t>(std::numeric_limits<long long>::max()))
        fail(describe(a) + ": value " + std::to_string(i) + " is too large");
    }
    if constexpr (std::is_floating_point_v<S> && !std::is_floating_point_v<T>) {
      const double d = v;
      if (!(d == std::floor(d)) || std::abs(d) > 9e15)
        fail(describe(a) + ": value " + std::to_string(i) + " is not an integer");
    }
    out[i] = static_cast<T>(v);
  }
}

bool VtuFile::read_native(const pugi::xml_node &a, Scalar type, void *dst,
                          std::size_t expected) const {
  const TypeInfo &ti = type_of(a);
  const std::string format = a.attribute("format").as_string("ascii");
  if (ti.type != type || (format != "binary" && format != "appended") ||
      big_endian_ != (std::endian::native == std::endian::big))
    return false;
  if (streamed_ && !compressed_ && format == "appended") {
    // Straight from the file into dst, after the same checks.
    const uint64_t offset = appended_offset(a, appended_length_);
    const uint64_t at = appended_begin_ + offset;
    const uint64_t n = raw_array_bytes(at, appended_length_ - offset, a);
    value_count(a, ti, n, expected);
    read_at(at + header_size_, static_cast<std::size_t>(n), dst);
    return true;
  }
  const Payload raw = binary_payload(a, uint64_t{expected} * ti.size);
  value_count(a, ti, raw.size, expected);
  if (raw.size > 0)
    std::memcpy(dst, raw.data, raw.size);
  return true;
}

template <class T>
void VtuFile::convert_payload(const Payload &raw, const pugi::xml_node &a,
                              PooledVector<T> &out) const {
  switch (type_of(a).type) {
  case Scalar::F32:
    convert_binary<float>(raw, a, out);
    break;
  case Scalar::F64:
    convert_binary<double>(raw, a, out);
    break;
  case Scalar::I8:
    convert_binary<int8_t>(raw, a, out);
    break;
  case Scalar::U8:
    convert_binary<uint8_t>(raw, a, out);
    break;
  case Scalar::I16:
    convert_binary<int16_t>(raw, a, out);
    break;
  case Scalar::U16:
    convert_binary<uint16_t>(raw, a, out);
    break;
  case Scalar::I32:
    convert_binary<int32_t>(raw, a, out);
    break;
  case Scalar::U32:
    convert_binary<uint32_t>(raw, a, out);
    break;
  case Scalar::I64:
    convert_binary<int64_t>(raw, a, out);
    break;
  case Scalar::U64:
    convert_binary<uint64_t>(raw, a, out);
    break;
  }
}
// For io/vtu_cell_range.cpp.
template void VtuFile::convert_payload(const Payload &, const pugi::xml_node &,
                                       PooledVector<double> &) const;
template void VtuFile::convert_payload(const Payload &, const pugi::xml_node &,
                                       PooledVector<int64_t> &) const;

template <class T>
PooledVector<T> VtuFile::read_array(const pugi::xml_node &a, std::size_t expected) const {
  const TypeInfo &ti = type_of(a);
  const std::string format = a.attribute("format").as_string("ascii");
  PooledVector<T> out;
  if (format == "ascii") {
    const char *p = a.child_value();
    const char *end = p + std::strlen(p);
    // A value takes at least two characters (a digit and a separator): never reserve more than
    // the text can hold, whatever the header counts claim.
    out.reserve(std::min(expected, static_cast<std::size_t>(end - p) / 2 + 1));
    std::size_t index = 0;
    while (true) {
      while (p < end && std::isspace(static_cast<unsigned char>(*p)))
        ++p;
      if (p >= end)
        break;
      if (out.size() >= expected)
        fail(describe(a) + ": more values than the " + std::to_string(expected) + " expected");
      if constexpr (std::is_same_v<T, double>) {
        double v;
        auto r = std::from_chars(p, end, v);
        if (r.ec != std::errc()) {
          // from_chars rejects "nan"/"inf" spellings VTK may write: parse them to report them.
          const std::string tok(p, std::find_if(p, end, [](char c) { return std::isspace(c); }));
          fail(describe(a) + ": value " + std::to_string(index) + " is not a number: '" + tok +
               "'");
        }
        p = r.ptr;
        out.push_back(v);
      } else {
        long long v;
        auto r = std::from_chars(p, end, v);
        if (r.ec != std::errc() ||
            (r.ptr < end && !std::isspace(static_cast<unsigned char>(*r.ptr)))) {
          const std::string tok(p, std::find_if(p, end, [](char c) { return std::isspace(c); }));
          fail(describe(a) + ": value " + std::to_string(index) + " is not an integer: '" + tok +
               "'");
        }
        p = r.ptr;
        out.push_back(static_cast<T>(v));
      }
      ++index;
    }
  } else if (format == "binary" || format == "appended") {
    // Stored as T in the machine's byte order: one copy (or read) straight into the result.
    constexpr Scalar native = std::is_same_v<T, double> ? Scalar::F64 : Scalar::I64;
    if (ti.type == native) {
      resize_mapped(out, expected);
      if (read_native(a, native, out.data(), expected))
        return out;
    }
    const Payload raw = binary_payload(a, uint64_t{expected} * ti.size);
    value_count(a, ti, raw.size, expected);
    convert_payload(raw, a, out);
  } else {
    fail(describe(a) + " has unknown format '" + format + "'");
  }
  if (out.size() != expected)
    fail(describe(a) + " has " + std::to_string(out.size()) + " values, expected " +
         std::to_string(expected));
  return out;
}

PooledVector<double> VtuFile::read_doubles(const pugi::xml_node &a, std::size_t expected) const {
  return read_array<double>(a, expected);
}
PooledVector<int64_t> VtuFile::read_ints(const pugi::xml_node &a, std::size_t expected) const {
  return read_array<int64_t>(a, expected);
}

long long parse_count(const pugi::xml_attribute &a) {
  if (!a)
    return -1;
  const char *s = a.as_string();
  long long v = -1;
  const auto r = std::from_chars(s, s + std::strlen(s), v);
  if (r.ec != std::errc() || *r.ptr != '\0')
    return -2;
  return v;
}

void VtuFile::check_rational_weights(const MeshInput &m, std::size_t first_cell,
                                     const pugi::xml_node &pd, std::size_t np, int64_t base,
                                     const std::string &where) const {
  bool bezier = false;
  for (std::size_t c = first_cell; c < m.num_cells() && !bezier; ++c)
    bezier = is_bezier(m.kind(c));
  if (!bezier || !pd)
    return;
  const char *named = pd.attribute("RationalWeights").as_string();
  const pugi::xml_node a = named_array(pd, *named ? named : "RationalWeights");
  if (!a)
    return;
  const PooledVector<double> w = read_doubles(a, np);
  for (std::size_t c = first_cell; c < m.num_cells(); ++c) {
    if (!is_bezier(m.kind(c)))
      continue;
    for (int64_t i = m.cell_offsets[c]; i < m.cell_offsets[c + 1]; ++i) {
      const std::size_t local = static_cast<std::size_t>(m.cell_nodes[i] - base);
      if (w[local] != 1.0)
        fail(where + ": cell " + std::to_string(c - first_cell) +
             " is a rational Bezier cell (RationalWeights at point " + std::to_string(local) +
             " is " + std::to_string(w[local]) +
             ", not 1): rational cells are not supported (their field is a ratio of two "
             "polynomials, which hoct's Bernstein bounds do not certify)");
    }
  }
}

std::vector<uint8_t> VtuFile::read_ghost(const pugi::xml_node &data, std::size_t n,
                                         const std::string &where) const {
  const pugi::xml_node a = named_array(data, "vtkGhostType");
  std::vector<uint8_t> flags;
  if (!a)
    return flags;
  if (a.attribute("NumberOfComponents").as_int(1) != 1)
    fail(where + ": " + describe(a) + " has " + a.attribute("NumberOfComponents").as_string() +
         " components (a ghost level has 1)");
  const PooledVector<int64_t> v = read_ints(a, n);
  flags.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (v[i] < 0 || v[i] > 255)
      fail(where + ": " + describe(a) + ": value " + std::to_string(i) + " is " +
           std::to_string(v[i]) + ", not a ghost flag (0 to 255)");
    flags[i] = static_cast<uint8_t>(v[i]);
  }
  return flags;
}

void VtuFile::read_point_arrays(const pugi::xml_node &pd, int64_t base, std::size_t np,
                                const std::string &where) {
  const std::size_t before = static_cast<std::size_t>(base);
  const std::vector<uint8_t> ghost = read_ghost(pd, np, where);
  if (!ghost.empty() || !arrays_.point_ghost.empty()) {
    arrays_.point_ghost.resize(before, 0); // zeros for earlier pieces without one
    if (ghost.empty())
      arrays_.point_ghost.resize(before + np, 0);
    for (const uint8_t g : ghost) {
      arrays_.point_ghost.push_back(g);
      arrays_.ghost_points += (g & kDuplicateGhost) != 0;
    }
  }
  std::string name = request_.global_ids_name;
  if (name.empty())
    name = pd.attribute("GlobalIds").as_string();
  if (name.empty())
    name = "GlobalIds";
  // Ids of every piece or of none: ids of some pieces only cannot join them.
  const pugi::xml_node a = named_array(pd, name);
  const bool usable = a && a.attribute("NumberOfComponents").as_int(1) == 1;
  const bool first = before == 0, earlier = !arrays_.global_ids.empty();
  if (usable != (first || earlier)) {
    ids_incomplete_ = ids_incomplete_ || !first;
    return;
  }
  if (!usable)
    return;
  const PooledVector<int64_t> ids = read_ints(a, np);
  arrays_.global_ids.insert(arrays_.global_ids.end(), ids.begin(), ids.end());
  arrays_.global_ids_name = name;
}

pugi::xml_node VtuFile::points_array(const pugi::xml_node &piece, const std::string &where,
                                     int &components) const {
  const pugi::xml_node pa = single_child(single_child(piece, "Points"), "DataArray");
  if (!pa)
    fail(where + ": no <Points> DataArray");
  components = pa.attribute("NumberOfComponents").as_int(1);
  if (components != 3 && components != 2)
    fail(where + ": Points have " + std::to_string(components) + " components (expected 3)");
  return pa;
}

std::array<pugi::xml_node, 3> VtuFile::cell_arrays(const pugi::xml_node &piece,
                                                   const std::string &where) const {
  const pugi::xml_node cells = single_child(piece, "Cells");
  const pugi::xml_node ca = named_array(cells, "connectivity"), oa = named_array(cells, "offsets"),
                       ta = named_array(cells, "types");
  if (!ca || !oa || !ta)
    fail(where + ": <Cells> needs the DataArrays connectivity, offsets and types");
  return {ca, oa, ta};
}

MeshInput VtuFile::read() {
  load();
  const pugi::xml_node grid = single_child(doc_.child("VTKFile"), "UnstructuredGrid");
  if (!grid)
    fail("no <UnstructuredGrid> element");
  MeshInput m;
  m.source = path_;
  m.cell_offsets.assign(1, 0);
  int piece_index = 0, read_pieces = 0;
  long long skipped = 0;
  for (auto piece : grid.children("Piece")) {
    const std::string where = "piece " + std::to_string(piece_index);
    const long long np = parse_count(piece.attribute("NumberOfPoints"));
    const long long nc = parse_count(piece.attribute("NumberOfCells"));
    if (np < 0 || nc < 0)
      fail(where + ": missing or bad NumberOfPoints / NumberOfCells");
    if (np == 0 && nc == 0) { // an empty piece (parallel writers' idle ranks): nothing to read
      ++piece_index;
      continue;
    }
    // Guard counts against the file size before allocating (a value needs >= 1 byte).
    if (static_cast<unsigned long long>(np) > file_size_ ||
        static_cast<unsigned long long>(nc) > file_size_)
      fail(where + ": NumberOfPoints " + std::to_string(np) + " / NumberOfCells " +
           std::to_string(nc) + " exceed what the file can hold");
    check_memory(limits_, m.points.size() + np, m.num_cells() + nc,
                 m.cell_nodes.size() + 3 * static_cast<uint64_t>(nc), path_ + ": " + where);
    const int64_t base = static_cast<int64_t>(m.points.size());
    // Points.
    int pc = 3;
    const pugi::xml_node pa = points_array(piece, where, pc);
    if (type_of(pa).type == Scalar::F32)
      m.coordinate_precision = 0x1p-24;
    resize_mapped(m.points, static_cast<std::size_t>(base + np));
    Vec3 *points = m.points.data() + base;
    // Float64 x, y, z as stored: straight into the points (the common case); else converted.
    if (pc != 3 || !read_native(pa, Scalar::F64, points, static_cast<std::size_t>(np) * 3)) {
      const PooledVector<double> xyz = read_doubles(pa, static_cast<std::size_t>(np) * pc);
      for (long long i = 0; i < np; ++i)
        points[i] = {xyz[i * pc], xyz[i * pc + 1], pc == 3 ? xyz[i * pc + 2] : 0.0};
    }
    for (long long i = 0; i < np; ++i) {
      const Vec3 &p = points[i];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        fail(where + ": point " + std::to_string(i) + " has a NaN or infinite coordinate");
    }
    // The field.
    const pugi::xml_node pd = single_child(piece, "PointData");
    const pugi::xml_node sa = choose_field(pd, where);
    const std::string field = field_.describe(sa.attribute("Name").as_string());
    if (read_pieces == 0)
      m.field_name = field;
    else if (field != m.field_name)
      fail(where + ": field '" + field + "' differs from the first piece's '" + m.field_name + "'");
    const int comps = sa.attribute("NumberOfComponents").as_int(1);
    if (type_of(sa).type == Scalar::F32)
      m.value_precision = 0x1p-24;
    PooledVector<double> vals;
    if (comps == 1) {
      vals = read_doubles(sa, static_cast<std::size_t>(np));
    } else { // one component, or the magnitude, of a vector array
      const PooledVector<double> all = read_doubles(sa, static_cast<std::size_t>(np) * comps);
      vals.resize(static_cast<std::size_t>(np));
      for (long long i = 0; i < np; ++i) {
        const double *v = all.data() + i * comps;
        if (field_.component >= 0) {
          vals[i] = v[field_.component];
        } else {
          double sum = 0;
          for (int k = 0; k < comps; ++k)
            sum += v[k] * v[k];
          vals[i] = std::sqrt(sum);
        }
      }
    }
    for (long long i = 0; i < np; ++i)
      if (!std::isfinite(vals[i]))
        fail(where + ": point " + std::to_string(i) + " has a non-finite value of '" + field + "'");
    read_point_arrays(pd, base, static_cast<std::size_t>(np), where);
    if (m.values.empty())
      m.values = std::move(vals);
    else
      m.values.insert(m.values.end(), vals.begin(), vals.end());
    // Cells.
    const auto [ca, oa, ta] = cell_arrays(piece, where);
    const PooledVector<int64_t> offsets = read_ints(oa, static_cast<std::size_t>(nc));
    const PooledVector<int64_t> types = read_ints(ta, static_cast<std::size_t>(nc));
    // vtkGhostType of the cells (kept for the triangles only, as the cells are).
    const std::vector<uint8_t> cell_ghost =
        read_ghost(single_child(piece, "CellData"), static_cast<std::size_t>(nc), where);
    if (!cell_ghost.empty())
      arrays_.cell_ghost.resize(m.num_cells(), 0); // zeros for earlier pieces without one
    const int64_t nconn = nc ? offsets.back() : 0;
    if (nconn < 0 || static_cast<unsigned long long>(nconn) > file_size_)
      fail(where + ": the last cell offset " + std::to_string(nconn) + " is invalid");
    check_memory(limits_, m.points.size(), m.num_cells() + nc,
                 m.cell_nodes.size() + static_cast<uint64_t>(nconn), path_ + ": " + where);
    // The connectivity becomes the cell nodes in place: each cell's ids are read out, put in
    // lattice order and written back at the next free position (never after where they were
    // read: skipped cells only close gaps), so no second array of the connectivity's size.
    const std::size_t start = m.cell_nodes.size();
    const std::size_t first_cell = m.num_cells();
    if (start == 0) {
      m.cell_nodes = read_ints(ca, static_cast<std::size_t>(nconn));
    } else {
      const PooledVector<int64_t> conn = read_ints(ca, static_cast<std::size_t>(nconn));
      m.cell_nodes.insert(m.cell_nodes.end(), conn.begin(), conn.end());
    }
    m.cell_offsets.reserve(m.cell_offsets.size() + static_cast<std::size_t>(nc));
    m.cell_degree.reserve(m.cell_degree.size() + static_cast<std::size_t>(nc));
    std::string problem;
    int64_t *nodes = m.cell_nodes.data() + start;
    int64_t write = 0;
    int64_t cell[kMaxVtkCellNodes];
    for (long long c = 0; c < nc; ++c) {
      const int64_t begin = c ? offsets[c - 1] : 0, end = offsets[c];
      if (end < begin)
        fail(where + ": cell " + std::to_string(c) + ": offsets decrease (" +
             std::to_string(begin) + " then " + std::to_string(end) + ")");
      if (end > nconn)
        fail(where + ": cell " + std::to_string(c) + ": offset " + std::to_string(end) +
             " is beyond the connectivity (" + std::to_string(nconn) + " values)");
      int degree = 0;
      CellKind kind = CellKind::LagrangeTriangle;
      const VtkCellResult r = vtk_cell_nodes(types[c], nodes + begin, end - begin, np, base, cell,
                                             &degree, &kind, &problem);
      if (r == VtkCellResult::Invalid)
        fail(where + ": cell " + std::to_string(c) + problem);
      if (r == VtkCellResult::Skipped) {
        ++skipped;
        continue;
      }
      const int64_t n = end - begin;
      std::copy(cell, cell + n, nodes + write);
      write += n;
      m.cell_offsets.push_back(static_cast<int64_t>(start) + write);
      m.cell_degree.push_back(static_cast<uint8_t>(degree));
      m.set_kind(m.cell_degree.size() - 1, kind);
      if (!cell_ghost.empty()) {
        arrays_.cell_ghost.push_back(cell_ghost[c]);
        arrays_.ghost_cells += (cell_ghost[c] & kDuplicateGhost) != 0;
      } else if (!arrays_.cell_ghost.empty()) {
        arrays_.cell_ghost.push_back(0);
      }
    }
    m.cell_nodes.resize(start + static_cast<std::size_t>(write));
    check_rational_weights(m, first_cell, pd, static_cast<std::size_t>(np), base, where);
    ++piece_index;
    ++read_pieces;
  }
  if (piece_index == 0)
    fail("no <Piece> in <UnstructuredGrid>");
  if (ids_incomplete_) { // ids of some pieces only: no use for joining them
    arrays_.global_ids.clear();
    arrays_.global_ids_name.clear();
  }
  if (m.num_cells() == 0 && m.points.empty() && skipped == 0 && request_.allow_empty)
    return m;
  if (m.num_cells() == 0)
    fail(skipped ? "the file has no surface cells (only " + std::to_string(skipped) +
                       " vertex or line cells)"
                 : std::string("the file has no cells"));
  return m;
}

} // namespace vtu_detail

using vtu_detail::VtuFile;

MeshInput read_vtu(const std::string &path, const FieldSelection &field, const ReadLimits &limits) {
  if (!field.default_step())
    throw InputError(path + ": --step / --time: a .vtu file holds one time step");
  VtuPieceArrays a;
  MeshInput m = read_vtu_piece(path, field, limits, {}, a);
  if (a.ghost_cells > 0 || a.ghost_points > 0)
    m.warnings.push_back(lone_piece_warning(path, a.ghost_cells, a.ghost_points));
  return m;
}

MeshInput read_vtu_piece(const std::string &path, const FieldSelection &field,
                         const ReadLimits &limits, const VtuPieceRequest &request,
                         VtuPieceArrays &arrays) {
  FieldSelection one_step = field;
  one_step.step = -1;
  one_step.time.reset();
  try {
    VtuFile f(path, one_step, limits, request);
    f.read_file();
    MeshInput m = f.read();
    arrays = std::move(f.arrays());
    return m;
  } catch (const VtuCompressorError &) {
    const ExternalReader *external = external_reader();
    if (!external || !external->read_vtu_piece)
      throw;
    return external->read_vtu_piece(path, one_step, limits, request, arrays);
  }
}

MeshInput read_vtu_buffer(std::string bytes, const std::string &name, const FieldSelection &field,
                          const ReadLimits &limits) {
  VtuFile f(name, field, limits);
  f.set_bytes(std::move(bytes));
  return f.read();
}

} // namespace hoct
