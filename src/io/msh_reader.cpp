// Reader for Gmsh MSH files: version 4.1 (ascii and binary) and 2.2 (ascii).
//
// What it reads:
//  - $MeshFormat: version 4.1 (file type 0 ascii, 1 binary with 8-byte size_t and the int 1 that
//    fixes the byte order) or 2.2 ascii. Other versions (4.0, 3.0, 2.x binary, ...) are rejected
//    with the version found.
//  - $Nodes: all entity blocks; parametric coordinates (parametric flag 1: as many as the entity's
//    dimension) are skipped. Node tags are arbitrary positive integers, possibly sparse.
//  - $Elements: complete Lagrange triangles (types 2, 9, 21, 23, 25, 42-46: degrees 1 to 10),
//    converted from Gmsh's node order to the canonical lattice order. Points and lines (0D and 1D
//    elements) are skipped; incomplete (serendipity) triangles and every other 2D or 3D type are
//    errors naming the element.
//  - $NodeData: the view named `scalar` (empty: the first view with one component). The name is
//    the first string tag; the integer tags are time step, components, number of values
//    (and partition). If several $NodeData blocks have the chosen name, the last time step in the
//    file is used: a block with another time step replaces the values read so far, a block with
//    the same time step (another partition of it) adds to them. Only the chosen view's values are
//    checked (finite); the others are parsed and dropped.
//  - Every other section ($Entities, $PhysicalNames, $Periodic, $ElementData, $Comments, ...) is
//    skipped up to its $End marker.
// Gmsh's view.write(view, file, append=True) repeats the whole mesh before the view: a node or
// triangle whose tag was seen before must be identical to it, and is then ignored.
//
// Result: cells in file order; points are the nodes the triangles use, in the order they were
// first defined in the file (nodes used only by points and lines are dropped, and need no value).
// Every node of every triangle must be in $Nodes and have a value in the chosen view.
//
// Errors are InputError messages "file:LINE: what" (ascii) or "file: byte OFFSET: what" (binary);
// problems of the file as a whole ("no $Nodes section") give the file name only. Every count read
// from the file is checked against the bytes left before anything is allocated for it.
#include "io/msh_reader.hpp"

#include "io/msh_element_types.hpp"
#include "io/msh_scanner.hpp"
#include "io/tag_index.hpp"
#include "poly/lagrange_node_order.hpp"
#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace hoct {
namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxDegree = 10;

std::string read_whole_file(const std::string &path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a .msh file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  const std::streamoff size = in.tellg();
  if (size < 0)
    throw InputError(path + ": cannot read");
  std::string data(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(data.data(), size))
    throw InputError(path + ": cannot read");
  return data;
}

std::string str(uint64_t v) { return std::to_string(v); }
std::string str(int64_t v) { return std::to_string(v); }
std::string str(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

class MshReader {
public:
  MshReader(const std::string &path, std::string data, FieldSelection field,
            const ReadLimits &limits)
      : s_(path, std::move(data)), field_(std::move(field)), scalar_(field_.name), limits_(limits) {
  }
  MeshInput read();

private:
  void read_format(std::size_t at);
  void read_nodes_41(std::size_t at);
  void read_nodes_22(std::size_t at);
  void read_elements_41(std::size_t at);
  void read_elements_22(std::size_t at);
  void read_node_data(std::size_t at);
  void skip_section(std::string_view name, std::size_t at);
  void expect_end(const char *marker);
  // Reads the four counts of a 4.1 $Nodes or $Elements header.
  // `at` is set to where the counts start.
  std::array<uint64_t, 4> section_header(const char *section, std::size_t &at);
  // Reads the element tags of one ascii element line after its tag; fails naming the element.
  void ascii_node_tags(uint64_t element, const MshElementType &type);

  void add_node(uint64_t tag, const Vec3 &p, std::size_t at);
  void add_triangle(uint64_t tag, int degree, std::size_t at);
  [[noreturn]] void reject_element(int64_t type, const MshElementType *t, uint64_t tag,
                                   std::size_t at) const;
  const std::vector<int> &gmsh_to_lattice(int degree);
  MeshInput finish();
  // The memory budget for these totals; the place (whose line takes a scan to find) is formatted
  // only when the budget is exceeded.
  void check_budget(uint64_t points, uint64_t cells, uint64_t cell_nodes, std::size_t at) const {
    if (limits_.max_memory_bytes &&
        estimate_memory_bytes(points, cells, cell_nodes) > limits_.max_memory_bytes)
      check_memory(limits_, points, cells, cell_nodes, s_.where(at));
  }
  [[noreturn]] void fail_file(const std::string &what) const {
    throw InputError(s_.path() + ": " + what);
  }

  MshScanner s_;
  FieldSelection field_;
  std::string scalar_; // field_.name
  ReadLimits limits_;
  bool have_format_ = false, have_nodes_ = false, have_elements_ = false;
  bool binary_ = false;
  int version_ = 0; // 41 or 22

  // Nodes, in order of first definition.
  TagIndex node_index_;
  PooledVector<Vec3> points_;
  std::vector<uint64_t> node_tags_;

  // Triangles with node indices into points_, canonical order; their element tags.
  MeshInput cells_;
  std::vector<uint64_t> cell_tags_;
  TagIndex element_index_;
  uint64_t skipped_elements_ = 0;
  std::array<const std::vector<int> *, kMaxDegree + 1> perms_{};

  // Scratch space for one block or element.
  std::vector<uint64_t> tags_;
  std::array<int64_t, lattice_size(kMaxDegree)> canonical_{};

  // Views: every name seen (with its number of components), and the chosen one's values per
  // node (NaN: no value).
  std::vector<std::pair<std::string, int64_t>> views_;
  bool have_chosen_ = false;
  std::string chosen_;
  int64_t chosen_step_ = 0;
  std::size_t chosen_at_ = 0;
  PooledVector<double> values_;
};

MeshInput MshReader::read() {
  while (s_.skip_space()) {
    const std::size_t at = s_.pos();
    const std::string_view name = s_.word("a section");
    if (name.size() < 2 || name[0] != '$')
      s_.fail_at(at, "expected a section such as $Nodes, got " + MshScanner::quote(name));
    const std::string_view section = name.substr(1);
    if (!have_format_ && section != "MeshFormat")
      s_.fail_at(at, "not a Gmsh MSH file: it must start with $MeshFormat, not " +
                         MshScanner::quote(name));
    if (section.substr(0, 3) == "End")
      s_.fail_at(at, MshScanner::quote(name) + " ends a section that was not started");
    if (section == "MeshFormat")
      read_format(at);
    else if (section == "Nodes")
      version_ == 41 ? read_nodes_41(at) : read_nodes_22(at);
    else if (section == "Elements")
      version_ == 41 ? read_elements_41(at) : read_elements_22(at);
    else if (section == "NodeData")
      read_node_data(at);
    else
      skip_section(section, at);
  }
  if (!have_format_)
    fail_file("the file is empty");
  return finish();
}

void MshReader::read_format(std::size_t at) {
  const std::size_t version_at = (s_.skip_space(), s_.pos());
  const std::string_view v = s_.word("the MSH version");
  double version = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), version);
  const bool parsed = r.ec == std::errc() && r.ptr == v.data() + v.size();
  const int found = !parsed                          ? 0
                    : std::abs(version - 4.1) < 1e-9 ? 41
                    : std::abs(version - 2.2) < 1e-9 ? 22
                                                     : 0;
  if (found == 0)
    s_.fail_at(version_at, "MSH version " + MshScanner::quote(v) +
                               " is not supported: hoct reads MSH 4.1 (ascii or binary) and 2.2 "
                               "(ascii); in Gmsh, save with Mesh.MshFileVersion = 4.1");
  const std::size_t type_at = (s_.line_ends(), s_.pos());
  const uint64_t file_type = s_.unsigned_number("the file type");
  const uint64_t data_size = s_.unsigned_number("the data size");
  s_.end_line("the data size");
  if (file_type > 1)
    s_.fail_at(type_at, "unknown file type " + str(file_type) + " (0 ascii, 1 binary)");
  const bool binary = file_type == 1;
  if (binary && found == 22)
    s_.fail_at(type_at, "binary MSH 2.2 is not supported: save as MSH 4.1 "
                        "(Mesh.MshFileVersion = 4.1) or as ascii");
  if (binary && data_size != 8)
    s_.fail_at(type_at, "binary data size " + str(data_size) +
                            " is not supported (hoct reads 8-byte size_t)");
  if (have_format_ && (found != version_ || binary != binary_))
    s_.fail_at(at, "a second $MeshFormat changes the format of the file");
  version_ = found;
  binary_ = binary;
  if (binary_) {
    s_.use_byte_offsets();
    const std::size_t one_at = s_.pos();
    const auto one = s_.get<int32_t>("the byte-order check");
    if (one == 0x01000000)
      s_.fail_at(one_at, "the binary data are big-endian; hoct reads little-endian files");
    if (one != 1)
      s_.fail_at(one_at, "the byte-order check is " + str(int64_t{one}) + ", not 1");
  }
  expect_end("$EndMeshFormat");
  have_format_ = true;
}

void MshReader::expect_end(const char *marker) {
  const std::string_view t = s_.word(marker);
  if (t != marker)
    s_.fail_at(s_.pos() - t.size(),
               std::string("expected ") + marker + ", got " + MshScanner::quote(t) +
                   " (the section holds more than its counts announce, or its end is missing)");
}

void MshReader::skip_section(std::string_view name, std::size_t at) {
  const std::string end = "$End" + std::string(name);
  const std::string_view data = s_.data();
  for (std::size_t from = s_.pos();;) {
    const std::size_t found = data.find(end, from);
    if (found == std::string_view::npos)
      s_.fail_at(at, "section $" + std::string(name) + " has no " + end);
    const std::size_t after = found + end.size();
    if (after == data.size() || std::isspace(static_cast<unsigned char>(data[after]))) {
      s_.seek(after);
      return;
    }
    from = found + 1;
  }
}

std::array<uint64_t, 4> MshReader::section_header(const char *section, std::size_t &at) {
  std::array<uint64_t, 4> h;
  if (binary_) {
    s_.end_line(section);
    at = s_.pos();
    s_.need(4 * sizeof(uint64_t), "the section header");
    for (auto &v : h)
      v = s_.get_unchecked<uint64_t>();
  } else {
    at = (s_.skip_space(), s_.pos());
    h[0] = s_.unsigned_number("the number of entity blocks", true);
    h[1] = s_.unsigned_number("the number of entries");
    h[2] = s_.unsigned_number("the minimum tag");
    h[3] = s_.unsigned_number("the maximum tag");
    s_.end_line("the section header");
  }
  return h;
}

void MshReader::add_node(uint64_t tag, const Vec3 &p, std::size_t at) {
  if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    s_.fail_at(at, "node " + str(tag) + " has a non-finite coordinate (" + str(p[0]) + " " +
                       str(p[1]) + " " + str(p[2]) + ")");
  const int64_t earlier = node_index_.insert(tag, static_cast<int64_t>(points_.size()));
  if (earlier == TagIndex::none) {
    points_.push_back(p);
    node_tags_.push_back(tag);
  } else if (points_[static_cast<std::size_t>(earlier)] != p) {
    s_.fail_at(at, "node " + str(tag) + " is defined twice, with different coordinates");
  }
}

void MshReader::read_nodes_41(std::size_t) {
  std::size_t header_at;
  const auto [blocks, total, min_tag, max_tag] = section_header("$Nodes", header_at);
  (void)min_tag, (void)max_tag;
  // At least: block header 3 ints + size_t (binary) or 4 numbers (ascii); node: tag and x y z.
  s_.check_count(blocks, binary_ ? 20 : 8, "node blocks", header_at);
  s_.check_count(total, binary_ ? 32 : 8, "nodes", header_at);
  check_budget(points_.size() + total, cells_.num_cells(), cells_.cell_nodes.size(), header_at);
  node_index_.allow_flat(2 * (points_.size() + total) + 1024);
  if (points_.empty()) {
    points_.reserve(total);
    node_tags_.reserve(total);
  }
  uint64_t seen = 0;
  for (uint64_t b = 0; b < blocks; ++b) {
    const std::size_t block_at = binary_ ? s_.pos() : (s_.skip_space(), s_.pos());
    int64_t dim, parametric;
    uint64_t n;
    if (binary_) {
      s_.need(3 * 4 + 8, "a node block header");
      dim = s_.get_unchecked<int32_t>();
      s_.get_unchecked<int32_t>(); // entity tag
      parametric = s_.get_unchecked<int32_t>();
      n = s_.get_unchecked<uint64_t>();
    } else {
      dim = s_.signed_number("the entity dimension", true);
      s_.signed_number("the entity tag");
      parametric = s_.signed_number("the parametric flag");
      n = s_.unsigned_number("the number of nodes in the block");
      s_.end_line("the node block header");
    }
    if (dim < 0 || dim > 3)
      s_.fail_at(block_at, "node block: entity dimension " + str(dim) + " is not 0 to 3");
    if (parametric != 0 && parametric != 1)
      s_.fail_at(block_at, "node block: parametric flag " + str(parametric) + " is not 0 or 1");
    const int extra = parametric ? static_cast<int>(dim) : 0;
    s_.check_count(n, binary_ ? 8 * (4 + extra) : 2 * (4 + extra), "nodes in the block", block_at);
    if (n > total - seen)
      s_.fail_at(block_at, "the node blocks hold more nodes than the " + str(total) +
                               " the $Nodes header announces");
    seen += n;
    tags_.resize(n);
    if (binary_) {
      const std::size_t tags_at = s_.pos();
      s_.need(8 * n, "the node tags");
      for (uint64_t i = 0; i < n; ++i)
        if ((tags_[i] = s_.get_unchecked<uint64_t>()) == 0)
          s_.fail_at(tags_at + 8 * i, "node tag 0 (tags are positive)");
      s_.need(8 * (3 + extra) * n, "the node coordinates");
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t node_at = s_.pos();
        Vec3 p;
        for (double &c : p)
          c = s_.get_unchecked<double>();
        s_.seek(s_.pos() + 8 * static_cast<std::size_t>(extra));
        add_node(tags_[i], p, node_at);
      }
    } else {
      for (uint64_t i = 0; i < n; ++i) {
        if ((tags_[i] = s_.unsigned_number("a node tag", true)) == 0)
          s_.fail("node tag 0 (tags are positive)");
        s_.end_line("a node tag (one per line)");
      }
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t node_at = (s_.skip_space(), s_.pos());
        Vec3 p;
        p[0] = s_.real_number("the x coordinate", true);
        p[1] = s_.real_number("the y coordinate");
        p[2] = s_.real_number("the z coordinate");
        for (int k = 0; k < extra; ++k)
          s_.real_number("a parametric coordinate");
        s_.end_line(extra ? "the parametric coordinates" : "the node coordinates");
        add_node(tags_[i], p, node_at);
      }
    }
  }
  if (seen != total)
    s_.fail("the $Nodes header announces " + str(total) + " nodes, its blocks hold " + str(seen));
  expect_end("$EndNodes");
  have_nodes_ = true;
}

void MshReader::read_nodes_22(std::size_t) {
  const std::size_t header_at = (s_.skip_space(), s_.pos());
  const uint64_t n = s_.unsigned_number("the number of nodes", true);
  s_.end_line("the number of nodes");
  s_.check_count(n, 8, "nodes", header_at);
  check_budget(points_.size() + n, cells_.num_cells(), cells_.cell_nodes.size(), header_at);
  node_index_.allow_flat(2 * (points_.size() + n) + 1024);
  for (uint64_t i = 0; i < n; ++i) {
    const std::size_t node_at = (s_.skip_space(), s_.pos());
    const uint64_t tag = s_.unsigned_number("a node tag", true);
    if (tag == 0)
      s_.fail_at(node_at, "node tag 0 (tags are positive)");
    Vec3 p;
    p[0] = s_.real_number("the x coordinate");
    p[1] = s_.real_number("the y coordinate");
    p[2] = s_.real_number("the z coordinate");
    s_.end_line("the node coordinates");
    add_node(tag, p, node_at);
  }
  expect_end("$EndNodes");
  have_nodes_ = true;
}

void MshReader::reject_element(int64_t type, const MshElementType *t, uint64_t tag,
                               std::size_t at) const {
  const std::string e = "element " + str(tag);
  if (!t)
    s_.fail_at(at, e + " has unknown element type " + str(type));
  if (t->incomplete_triangle())
    s_.fail_at(at, e + ": incomplete (serendipity) triangle type " + str(type) +
                       " is not supported (Gmsh's " + t->name +
                       "): hoct needs complete Lagrange triangles (in Gmsh, "
                       "Mesh.SecondOrderIncomplete = 0)");
  s_.fail_at(at, e + " has element type " + str(type) + " (" + t->name +
                     "), which is not a triangle: hoct reads triangle meshes");
}

const std::vector<int> &MshReader::gmsh_to_lattice(int degree) {
  auto &p = perms_[static_cast<std::size_t>(degree)];
  if (!p)
    p = &node_order_to_lattice(NodeOrdering::Gmsh, degree);
  return *p;
}

// The triangle's node tags are in tags_, in Gmsh order.
void MshReader::add_triangle(uint64_t tag, int degree, std::size_t at) {
  if (tag == 0)
    s_.fail_at(at, "element tag 0 (tags are positive)");
  const std::vector<int> &perm = gmsh_to_lattice(degree);
  const std::size_t n = perm.size();
  for (std::size_t i = 0; i < n; ++i) {
    const int64_t node = node_index_.find(tags_[i]);
    if (node == TagIndex::none)
      s_.fail_at(at, "element " + str(tag) + " refers to node " + str(tags_[i]) +
                         ", which is not in $Nodes");
    canonical_[static_cast<std::size_t>(perm[i])] = node;
  }
  const auto cell = static_cast<int64_t>(cells_.num_cells());
  const int64_t earlier = element_index_.insert(tag, cell);
  if (earlier == TagIndex::none) {
    cells_.add_cell(degree, canonical_.data());
    cell_tags_.push_back(tag);
    return;
  }
  const auto e = static_cast<std::size_t>(earlier);
  if (cells_.cell_degree[e] != degree ||
      !std::equal(canonical_.begin(), canonical_.begin() + static_cast<std::ptrdiff_t>(n),
                  cells_.cell_nodes.begin() + cells_.cell_offsets[e]))
    s_.fail_at(at, "element " + str(tag) + " is defined twice, with different nodes");
}

void MshReader::ascii_node_tags(uint64_t element, const MshElementType &type) {
  const auto nodes = static_cast<std::size_t>(type.nodes);
  for (std::size_t k = 0; k < nodes; ++k) {
    if (s_.line_ends())
      s_.fail("element " + str(element) + " (" + type.name + ") has " + str(uint64_t{k}) +
              " node tags on its line, expected " + str(uint64_t{nodes}));
    tags_[k] = s_.unsigned_number("a node tag");
  }
  if (!s_.line_ends())
    s_.fail("element " + str(element) + " (" + type.name + ") has more than " +
            str(uint64_t{nodes}) + " node tags on its line");
  s_.end_line("the element");
}

void MshReader::read_elements_41(std::size_t at) {
  if (!have_nodes_)
    s_.fail_at(at, "$Elements before any $Nodes section: the nodes must come first");
  std::size_t header_at;
  const auto [blocks, total, min_tag, max_tag] = section_header("$Elements", header_at);
  (void)min_tag, (void)max_tag;
  s_.check_count(blocks, binary_ ? 20 : 8, "element blocks", header_at);
  s_.check_count(total, binary_ ? 16 : 4, "elements", header_at);
  // Every element could be a triangle (3 nodes at least); points and lines are skipped later.
  check_budget(points_.size(), cells_.num_cells() + total, cells_.cell_nodes.size() + 3 * total,
               header_at);
  element_index_.allow_flat(2 * (cells_.num_cells() + total) + 1024);
  uint64_t seen = 0;
  for (uint64_t b = 0; b < blocks; ++b) {
    const std::size_t block_at = binary_ ? s_.pos() : (s_.skip_space(), s_.pos());
    int64_t dim, type;
    uint64_t n;
    if (binary_) {
      s_.need(3 * 4 + 8, "an element block header");
      dim = s_.get_unchecked<int32_t>();
      s_.get_unchecked<int32_t>(); // entity tag
      type = s_.get_unchecked<int32_t>();
      n = s_.get_unchecked<uint64_t>();
    } else {
      dim = s_.signed_number("the entity dimension", true);
      s_.signed_number("the entity tag");
      type = s_.signed_number("the element type");
      n = s_.unsigned_number("the number of elements in the block");
      s_.end_line("the element block header");
    }
    if (dim < 0 || dim > 3)
      s_.fail_at(block_at, "element block: entity dimension " + str(dim) + " is not 0 to 3");
    const bool type_fits = type > 0 && type <= std::numeric_limits<int>::max();
    const MshElementType *t = type_fits ? msh_element_type(static_cast<int>(type)) : nullptr;
    const uint64_t nodes = t ? static_cast<uint64_t>(t->nodes) : 0;
    s_.check_count(n, binary_ ? 8 * (1 + nodes) : 2 * (1 + nodes), "elements in the block",
                   block_at);
    if (n > total - seen)
      s_.fail_at(block_at, "the element blocks hold more elements than the " + str(total) +
                               " the $Elements header announces");
    seen += n;
    if (n == 0)
      continue;
    const int degree = t ? t->complete_triangle_degree() : 0;
    if (!t || (t->dimension >= 2 && degree == 0)) {
      // Name the block's first element.
      const std::size_t first_at = binary_ ? s_.pos() : (s_.skip_space(), s_.pos());
      const uint64_t first =
          binary_ ? s_.get<uint64_t>("an element tag") : s_.unsigned_number("an element tag", true);
      reject_element(type, t, first, first_at);
    }
    tags_.resize(nodes);
    if (binary_) {
      s_.need(8 * (1 + nodes) * n, "the element block");
      if (degree == 0) { // points and lines
        s_.skip(8 * (1 + nodes) * n, "the element block");
        skipped_elements_ += n;
        continue;
      }
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t element_at = s_.pos();
        const uint64_t tag = s_.get_unchecked<uint64_t>();
        for (auto &node : tags_)
          node = s_.get_unchecked<uint64_t>();
        add_triangle(tag, degree, element_at);
      }
    } else {
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t element_at = (s_.skip_space(), s_.pos());
        const uint64_t tag = s_.unsigned_number("an element tag", true);
        ascii_node_tags(tag, *t);
        if (degree == 0)
          ++skipped_elements_;
        else
          add_triangle(tag, degree, element_at);
      }
    }
  }
  if (seen != total)
    s_.fail("the $Elements header announces " + str(total) + " elements, its blocks hold " +
            str(seen));
  expect_end("$EndElements");
  have_elements_ = true;
}

void MshReader::read_elements_22(std::size_t at) {
  if (!have_nodes_)
    s_.fail_at(at, "$Elements before any $Nodes section: the nodes must come first");
  const std::size_t header_at = (s_.skip_space(), s_.pos());
  const uint64_t n = s_.unsigned_number("the number of elements", true);
  s_.end_line("the number of elements");
  s_.check_count(n, 8, "elements", header_at); // tag, type, number of tags, a node
  check_budget(points_.size(), cells_.num_cells() + n, cells_.cell_nodes.size() + 3 * n, header_at);
  element_index_.allow_flat(2 * (cells_.num_cells() + n) + 1024);
  for (uint64_t i = 0; i < n; ++i) {
    const std::size_t element_at = (s_.skip_space(), s_.pos());
    const uint64_t tag = s_.unsigned_number("an element tag", true);
    const int64_t type = s_.signed_number("the element type");
    const uint64_t ntags = s_.unsigned_number("the number of element tags");
    for (uint64_t k = 0; k < ntags; ++k)
      s_.signed_number("an element tag (physical, elementary, ...)");
    const bool type_fits = type > 0 && type <= std::numeric_limits<int>::max();
    const MshElementType *t = type_fits ? msh_element_type(static_cast<int>(type)) : nullptr;
    const int degree = t ? t->complete_triangle_degree() : 0;
    if (!t || (t->dimension >= 2 && degree == 0))
      reject_element(type, t, tag, element_at);
    tags_.resize(static_cast<std::size_t>(t->nodes));
    ascii_node_tags(tag, *t);
    if (degree == 0)
      ++skipped_elements_;
    else
      add_triangle(tag, degree, element_at);
  }
  expect_end("$EndElements");
  have_elements_ = true;
}

void MshReader::read_node_data(std::size_t at) {
  if (!have_nodes_)
    s_.fail_at(at, "$NodeData before any $Nodes section: the nodes must come first");
  // The header is ascii in binary files too: counts and tags one per line.
  auto count = [&](const char *what, const char *items) {
    const std::size_t count_at = (s_.skip_space(), s_.pos());
    const uint64_t n = s_.unsigned_number(what, true);
    s_.end_line(what);
    s_.check_count(n, 2, items, count_at);
    return n;
  };
  const uint64_t nstrings = count("the number of string tags", "string tags");
  std::string name;
  for (uint64_t i = 0; i < nstrings; ++i) {
    if (!s_.skip_space())
      s_.fail("unexpected end of file: expected a string tag");
    const std::size_t tag_at = s_.pos();
    std::string_view t = s_.rest_of_line();
    if (!t.empty() && t[0] == '"') {
      if (t.size() < 2 || t.back() != '"')
        s_.fail_at(tag_at, "unterminated string tag " + MshScanner::quote(t));
      t = t.substr(1, t.size() - 2);
    }
    if (i == 0)
      name = t;
  }
  const uint64_t nreals = count("the number of real tags", "real tags");
  for (uint64_t i = 0; i < nreals; ++i) {
    s_.real_number("a real tag (time)", true);
    s_.end_line("a real tag");
  }
  const std::size_t ints_at = (s_.skip_space(), s_.pos());
  const uint64_t nints = count("the number of integer tags", "integer tags");
  if (nints < 3)
    s_.fail_at(ints_at, "$NodeData '" + name + "' has " + str(nints) +
                            " integer tags; it needs 3 (time step, number of components, number "
                            "of values)");
  std::array<int64_t, 3> ints{};
  for (uint64_t i = 0; i < nints; ++i) {
    const int64_t v = s_.signed_number("an integer tag", true);
    s_.end_line("an integer tag");
    if (i < 3)
      ints[i] = v;
  }
  const auto [step, components, values] = ints;
  if (components < 1 || components > 9)
    s_.fail_at(ints_at, "$NodeData '" + name + "' has " + str(components) + " components");
  if (values < 0)
    s_.fail_at(ints_at, "$NodeData '" + name + "' has " + str(values) + " values");
  const auto comps = static_cast<uint64_t>(components);
  const auto n = static_cast<uint64_t>(values);
  const uint64_t record = binary_ ? 4 + 8 * comps : 2 * (1 + comps);
  s_.check_count(n, record, "values", ints_at);

  bool seen_name = false;
  for (auto &v : views_)
    if (v.first == name) {
      v.second = components;
      seen_name = true;
    }
  if (!seen_name)
    views_.emplace_back(name, components);
  const bool vector = field_.component != FieldSelection::kScalar;
  const bool collect = !scalar_.empty() ? name == scalar_
                       : have_chosen_   ? name == chosen_
                                        : (vector ? components > 1 : components == 1) &&
                                            !is_bookkeeping_array(std::string(name));
  if (collect && !vector && components != 1)
    s_.fail_at(at, "$NodeData '" + name + "' has " + str(components) +
                       " components; a scalar field needs 1 (choose one with --component N, or "
                       "--component magnitude)");
  if (collect && vector && components == 1)
    s_.fail_at(at, "--component: $NodeData '" + name + "' has one component");
  if (collect && field_.component >= components)
    s_.fail_at(at, "--component " + str(int64_t{field_.component}) + ": $NodeData '" + name +
                       "' has " + str(components) + " components (0 to " + str(components - 1) +
                       ")");
  // The value a node's components give: the one, the chosen component, or the magnitude.
  double comp[9];
  const int64_t ncomp = components; // (a structured binding: lambdas capture a copy)
  auto combined = [&]() {
    if (field_.component >= 0)
      return comp[field_.component];
    if (!vector)
      return comp[0];
    double sum = 0;
    for (int64_t k = 0; k < ncomp; ++k)
      sum += comp[k] * comp[k];
    return std::sqrt(sum);
  };
  if (collect) {
    if (!have_chosen_ || step != chosen_step_)
      values_.assign(points_.size(), kNoValue); // a later time step replaces the earlier
    else
      values_.resize(points_.size(), kNoValue); // another partition of the same time step
    have_chosen_ = true;
    chosen_ = name;
    chosen_step_ = step;
    chosen_at_ = at;
  }

  auto store = [&](uint64_t tag, double v, std::size_t value_at) {
    if (!std::isfinite(v))
      s_.fail_at(value_at, "$NodeData '" + name + "': node " + str(tag) +
                               " has a non-finite value (" + str(v) + ")");
    const int64_t node = node_index_.find(tag);
    if (node != TagIndex::none)
      values_[static_cast<std::size_t>(node)] = v;
  };
  if (binary_) {
    s_.need(record * n, "the $NodeData values");
    if (!collect) {
      s_.skip(record * n, "the $NodeData values");
    } else {
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t tag_at = s_.pos();
        const auto tag = s_.get_unchecked<int32_t>();
        if (tag <= 0)
          s_.fail_at(tag_at, "$NodeData '" + name + "': node tag " + str(int64_t{tag}) +
                                 " is not positive");
        for (uint64_t k = 0; k < comps; ++k)
          comp[k] = s_.get_unchecked<double>();
        store(static_cast<uint64_t>(tag), combined(), tag_at + 4);
      }
    }
  } else {
    for (uint64_t i = 0; i < n; ++i) {
      const uint64_t tag = s_.unsigned_number("a node tag", true);
      const std::size_t value_at = (s_.line_ends(), s_.pos());
      for (uint64_t k = 0; k < comps; ++k)
        comp[k] = s_.real_number("a value");
      s_.end_line(comps == 1 ? "the node's value" : "the node's values");
      if (collect)
        store(tag, combined(), value_at);
    }
  }
  expect_end("$EndNodeData");
}

MeshInput MshReader::finish() {
  if (!have_nodes_)
    fail_file("no $Nodes section");
  if (!have_elements_)
    fail_file("no $Elements section");
  if (cells_.num_cells() == 0)
    fail_file("no triangles in $Elements (" + str(skipped_elements_) +
              " point and line elements skipped)");
  if (!have_chosen_) {
    if (views_.empty())
      fail_file("the file has no node data: it holds a mesh but no $NodeData section with a "
                "scalar field (in Gmsh, add a view and write it after the mesh, e.g. "
                "gmsh.view.write(view, file, append=True))");
    std::string names;
    for (const auto &v : views_)
      names += (names.empty() ? "" : ", ") + v.first +
               (v.second == 1 ? "" : " (" + str(v.second) + " components)");
    if (!scalar_.empty())
      fail_file("no $NodeData named '" + scalar_ + "' (available: " + names + ")");
    fail_file("no scalar $NodeData (available: " + names + ")");
  }

  // Every node of every triangle needs a value; the nodes used are kept, in file order.
  values_.resize(points_.size(), kNoValue);
  std::vector<int64_t> renumber(points_.size(), -1);
  for (std::size_t c = 0; c < cells_.num_cells(); ++c)
    for (auto k = cells_.cell_offsets[c]; k < cells_.cell_offsets[c + 1]; ++k) {
      const auto node = static_cast<std::size_t>(cells_.cell_nodes[static_cast<std::size_t>(k)]);
      if (std::isnan(values_[node]))
        s_.fail_at(chosen_at_, "$NodeData '" + chosen_ + "' has no value for node " +
                                   str(node_tags_[node]) + " (of element " + str(cell_tags_[c]) +
                                   ")");
      renumber[node] = 0;
    }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (renumber[i] == 0) {
      renumber[i] = static_cast<int64_t>(kept);
      points_[kept] = points_[i];
      values_[kept] = values_[i];
      ++kept;
    }
  points_.resize(kept);
  values_.resize(kept);

  MeshInput m = std::move(cells_);
  for (auto &node : m.cell_nodes)
    node = renumber[static_cast<std::size_t>(node)];
  m.points = std::move(points_);
  m.values = std::move(values_);
  m.field_name = field_.describe(chosen_);
  m.source = s_.path();
  return m;
}

} // namespace

MeshInput read_msh(const std::string &path, const FieldSelection &field, const ReadLimits &limits) {
  if (!field.default_step())
    throw InputError(path + ": --step / --time: choosing a time step of a Gmsh view is not "
                            "supported yet (the last step of the view is read)");
  return MshReader(path, read_whole_file(path), field, limits).read();
}

MeshInput read_msh_buffer(std::string bytes, const std::string &name, const FieldSelection &field,
                          const ReadLimits &limits) {
  return MshReader(name, std::move(bytes), field, limits).read();
}

} // namespace hoct
