// Reader for Gmsh MSH files: version 4.1 and 2.2, ascii and binary.
//
// What it reads:
//  - $MeshFormat: version 4.1 or 2.2, file type 0 ascii or 1 binary (8-byte size_t, followed
//    by the int 1 that fixes the byte order: big-endian files are refused). Other versions (4.0,
//    3.0, ...) are rejected with the version found.
//  - $Nodes: all entity blocks (4.1); parametric coordinates (parametric flag 1: as many as the
//    entity's dimension) are skipped. Node tags are arbitrary positive integers, possibly sparse.
//    Binary 2.2: per node an int tag and three doubles.
//  - $Elements: complete Lagrange triangles (types 2, 9, 21, 23, 25, 42-46: degrees 1 to 10),
//    converted from Gmsh's node order to the canonical lattice order. Points and lines (0D and 1D
//    elements) are skipped; incomplete (serendipity) triangles and every other 2D or 3D type are
//    errors naming the element. Binary 2.2: blocks of a header (type, count, number of tags)
//    followed by that many elements (tag, tags, nodes; ints).
//  - Views: $NodeData (a value per node) and $ElementNodeData (per element, a value at each of
//    its nodes, in Gmsh's order of them), one view being all blocks of a name (the first string
//    tag); the integer tags are time step, components, number of values (and partition), the
//    first real tag the time. The view is `field.name` (empty: the first view with one component
//    that is no id array); its time steps are the distinct time-step tags in file order, and
//    `field.step` (from 0, negative from the end, default the last) or `field.time` (within 1e-9
//    relative) chooses one. The blocks of that step are merged (partitions). $ElementNodeData
//    values are merged into node values where the elements sharing a node agree within 1e-9 of
//    the view's range (plus rounding); else the file is refused naming the node, the elements and
//    the largest jump. A view whose blocks name an interpolation scheme (a second string tag;
//    Gmsh names one for every high-order view) is read if the scheme's triangle basis is the
//    Lagrange basis of the elements' nodes (its values are then node values), else refused.
//    $ElementData (one value per element) is listed, and
//    refused if chosen: a piecewise-constant field has no contour tree of this kind.
//    All blocks are parsed (every view's syntax is checked) and only the chosen step's values are
//    read and checked (finite) after the whole file, so views may come before or after a repeated
//    mesh.
//  - Every other section ($Entities, $PhysicalNames, $Periodic,
//    $Comments, ...) is skipped up to its $End marker.
// Gmsh's view.write(view, file, append=True) repeats the whole mesh before the view: a node or
// triangle whose tag was seen before must be identical to it, and is then ignored.
//
// Result: cells in file order; points are the nodes the triangles use, in the order they were
// first defined in the file (nodes used only by points and lines are dropped, and need no value).
// Every node of every triangle must be in $Nodes and have a value in the chosen view. With several
// time steps, MeshInput::field_detail says which was read: "(step 2 of 3, time 0.2)".
//
// Errors are InputError messages "file:LINE: what" (ascii) or "file: byte OFFSET: what" (binary);
// problems of the file as a whole ("no $Nodes section") give the file name only. Every count read
// from the file is checked against the bytes left before anything is allocated for it.
#include "io/msh_reader.hpp"

#include "io/file_contents.hpp"

#include "io/field_selection.hpp"
#include "io/msh_element_types.hpp"
#include "io/msh_interpolation_scheme.hpp"
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
#include <optional>

namespace hoct {
namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxDegree = 10;

enum class DataKind { Node, ElementNode, Element };

const char *section_of(DataKind k) {
  return k == DataKind::Node          ? "$NodeData"
         : k == DataKind::ElementNode ? "$ElementNodeData"
                                      : "$ElementData";
}

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
            const ReadLimits &limits, FileContents *contents)
      : s_(path, std::move(data)), field_(std::move(field)), scalar_(field_.name), limits_(limits),
        contents_(contents) {}
  MeshInput read();

private:
  void read_format(std::size_t at);
  void read_nodes_41(std::size_t at);
  void read_nodes_22(std::size_t at);
  void read_elements_41(std::size_t at);
  void read_elements_22(std::size_t at);
  void read_elements_22_binary(uint64_t total);
  void skip_element(uint64_t tag) {
    skipped_index_.insert(tag, 0);
    ++skipped_elements_;
  }
  void read_data(std::size_t at, DataKind kind);
  void skip_section(std::string_view name, std::size_t at);
  void read_interpolation_scheme(std::size_t at);
  std::vector<MshInterpolationScheme> schemes_;
  void expect_end(const char *marker);
  // Reads the four counts of a 4.1 $Nodes or $Elements header.
  // `at` is set to where the counts start.
  std::array<uint64_t, 4> section_header(const char *section, std::size_t &at);
  // Reads the element tags of one ascii element line after its tag; fails naming the element.
  void ascii_node_tags(uint64_t element, const MshElementType &type);

  void add_node(uint64_t tag, const Vec3 &p, std::size_t at);
  void add_surface_cell(uint64_t tag, CellKind kind, int degree, std::size_t at);
  [[noreturn]] void reject_element(int64_t type, const MshElementType *t, uint64_t tag,
                                   std::size_t at) const;
  const std::vector<int> &gmsh_to_lattice(int degree);
  // Gmsh's order to the canonical one for a cell of this kind and degree.
  const std::vector<int> &gmsh_to_canonical(CellKind kind, int degree);
  MeshInput finish();

  // A $NodeData, $ElementNodeData or $ElementData section: its header, and where its values are.
  struct DataBlock {
    DataKind kind = DataKind::Node;
    std::string name;
    int64_t step = 0, components = 1;
    uint64_t count = 0;
    std::optional<double> time;
    std::size_t at = 0, values_at = 0;
    std::string scheme; // the interpolation scheme an $ElementNodeData names (string tag 2)
  };
  // A view: the blocks of one name, with its time steps in file order.
  struct View {
    std::string name;
    DataKind kind;
    int64_t components;
    std::size_t at; // its first block
    std::vector<FileFieldStep> steps;
    std::string scheme;        // an interpolation scheme one of its blocks names
    std::size_t scheme_at = 0; // that block
    int64_t scheme_index = -1; // in schemes_: the scheme of that name defined before it
  };
  // Reads the values of a block (the scanner at its values_at): only checked for syntax and
  // skipped, or (collect) stored as the field.
  void scan_values(const DataBlock &b, bool collect);
  void merge_value(std::size_t node, double v, uint64_t element);
  // Chooses the view and its step (field_), and reads its values into values_.
  void choose_view();
  void check_continuity(const std::string &what) const;
  std::string available() const;
  static std::string step_list(const View &v);
  void fill_contents() const;
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
  FileContents *contents_;
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
  TagIndex skipped_index_; // point and line elements (their $ElementNodeData is ignored)
  uint64_t skipped_elements_ = 0;
  std::array<const std::vector<int> *, kMaxDegree + 1> perms_{};

  // Scratch space for one block or element.
  std::vector<uint64_t> tags_;
  std::array<int64_t, (kMaxDegree + 1) * (kMaxDegree + 1)> canonical_{}; // a quadrangle's too

  // Every data block and view, in file order; the chosen one's values per node (NaN: no value)
  // and, for $ElementNodeData, the lowest and highest value each node was given, and by which
  // elements.
  std::vector<DataBlock> blocks_;
  std::vector<View> views_;
  std::string chosen_, chosen_what_, chosen_detail_;
  std::size_t chosen_at_ = 0;
  PooledVector<double> values_;
  std::vector<double> lo_, hi_;
  std::vector<uint64_t> lo_element_, hi_element_;
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
      read_data(at, DataKind::Node);
    else if (section == "ElementNodeData")
      read_data(at, DataKind::ElementNode);
    else if (section == "ElementData")
      read_data(at, DataKind::Element);
    else if (section == "InterpolationScheme")
      read_interpolation_scheme(at);
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
                               " is not supported: hoct reads MSH 4.1 and 2.2 (ascii or "
                               "binary); in Gmsh, save with Mesh.MshFileVersion = 4.1");
  const std::size_t type_at = (s_.line_ends(), s_.pos());
  const uint64_t file_type = s_.unsigned_number("the file type");
  const uint64_t data_size = s_.unsigned_number("the data size");
  s_.end_line("the data size");
  if (file_type > 1)
    s_.fail_at(type_at, "unknown file type " + str(file_type) + " (0 ascii, 1 binary)");
  const bool binary = file_type == 1;
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

// $InterpolationScheme: "name", the number of topologies, and for each its id (3: triangle), the
// number of matrices and each matrix as "rows cols" and its values. Text in binary files too.
void MshReader::read_interpolation_scheme(std::size_t at) {
  MshInterpolationScheme scheme;
  scheme.at = at;
  if (!s_.skip_space())
    s_.fail("unexpected end of file: expected the interpolation scheme's name");
  std::string_view name = s_.rest_of_line();
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
    name = name.substr(1, name.size() - 2);
  scheme.name = name;
  constexpr uint64_t kMaxSide = 1000; // a degree-43 triangle
  const uint64_t topologies = s_.unsigned_number("the number of topologies", true);
  if (topologies > 64)
    s_.fail_at(at,
               "$InterpolationScheme '" + scheme.name + "' has " + str(topologies) + " topologies");
  for (uint64_t t = 0; t < topologies; ++t) {
    const uint64_t topology = s_.unsigned_number("a topology", true);
    const uint64_t matrices = s_.unsigned_number("the number of matrices", true);
    if (matrices > 8)
      s_.fail_at(at, "$InterpolationScheme '" + scheme.name + "' has " + str(matrices) +
                         " matrices for a topology");
    for (uint64_t m = 0; m < matrices; ++m) {
      const std::size_t matrix_at = (s_.skip_space(), s_.pos());
      const uint64_t rows = s_.unsigned_number("a matrix's rows", true);
      const uint64_t cols = s_.unsigned_number("a matrix's columns", true);
      if (rows > kMaxSide || cols > kMaxSide)
        s_.fail_at(matrix_at, "$InterpolationScheme '" + scheme.name + "': a " + str(rows) + " x " +
                                  str(cols) + " matrix (at most " + str(kMaxSide) + " x " +
                                  str(kMaxSide) + ")");
      std::vector<double> values(rows * cols);
      for (double &v : values)
        v = s_.real_number("a matrix entry", true);
      if (topology != 3)
        continue;
      if (m == 0) {
        scheme.rows = static_cast<int>(rows);
        scheme.cols = static_cast<int>(cols);
        scheme.coefficients = std::move(values);
      } else if (m == 1) {
        if (rows != static_cast<uint64_t>(scheme.cols))
          s_.fail_at(matrix_at, "$InterpolationScheme '" + scheme.name + "': " + str(rows) +
                                    " exponent rows for " +
                                    str(static_cast<uint64_t>(scheme.cols)) + " monomials");
        scheme.exponent_columns = static_cast<int>(cols);
        scheme.exponents = std::move(values);
      }
    }
  }
  if (!s_.skip_space() || s_.word("$EndInterpolationScheme") != "$EndInterpolationScheme")
    s_.fail_at(at, "$InterpolationScheme '" + scheme.name + "' has no $EndInterpolationScheme");
  schemes_.push_back(std::move(scheme));
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
  s_.check_count(n, binary_ ? 28 : 8, "nodes", header_at); // binary: int tag, 3 doubles
  check_budget(points_.size() + n, cells_.num_cells(), cells_.cell_nodes.size(), header_at);
  node_index_.allow_flat(2 * (points_.size() + n) + 1024);
  if (binary_) {
    s_.need(28 * n, "the nodes");
    for (uint64_t i = 0; i < n; ++i) {
      const std::size_t node_at = s_.pos();
      const auto tag = s_.get_unchecked<int32_t>();
      if (tag <= 0)
        s_.fail_at(node_at, "node tag " + str(int64_t{tag}) + " (tags are positive)");
      Vec3 p;
      for (double &c : p)
        c = s_.get_unchecked<double>();
      add_node(static_cast<uint64_t>(tag), p, node_at);
    }
    expect_end("$EndNodes");
    have_nodes_ = true;
    return;
  }
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
                     "), which is not a surface cell hoct reads (triangles and quadrangles)");
}

const std::vector<int> &MshReader::gmsh_to_lattice(int degree) {
  auto &p = perms_[static_cast<std::size_t>(degree)];
  if (!p)
    p = &node_order_to_lattice(NodeOrdering::Gmsh, degree);
  return *p;
}

const std::vector<int> &MshReader::gmsh_to_canonical(CellKind kind, int degree) {
  switch (kind) {
  case CellKind::LagrangeQuadrilateral:
    return quad_node_order_to_tensor(NodeOrdering::Gmsh, degree);
  case CellKind::SerendipityQuadrilateral:
    return serendipity_node_order(NodeOrdering::Gmsh, degree);
  default:
    return gmsh_to_lattice(degree);
  }
}

// The cell's node tags are in tags_, in Gmsh order.
void MshReader::add_surface_cell(uint64_t tag, CellKind kind, int degree, std::size_t at) {
  if (tag == 0)
    s_.fail_at(at, "element tag 0 (tags are positive)");
  const std::vector<int> &perm = gmsh_to_canonical(kind, degree);
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
    cells_.add_cell(kind, degree, canonical_.data());
    cell_tags_.push_back(tag);
    return;
  }
  const auto e = static_cast<std::size_t>(earlier);
  if (cells_.cell_degree[e] != degree || cells_.kind(e) != kind ||
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
  skipped_index_.allow_flat(2 * (skipped_elements_ + total) + 1024);
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
    const int degree = t ? t->surface_degree() : 0;
    const CellKind kind = t ? t->surface_kind() : CellKind::LagrangeTriangle;
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
        skipped_index_.allow_flat(2 * (skipped_elements_ + n) + 1024);
        for (uint64_t i = 0; i < n; ++i) {
          skipped_index_.insert(s_.get_unchecked<uint64_t>(), 0);
          s_.skip(8 * nodes, "the element");
        }
        skipped_elements_ += n;
        continue;
      }
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t element_at = s_.pos();
        const uint64_t tag = s_.get_unchecked<uint64_t>();
        for (auto &node : tags_)
          node = s_.get_unchecked<uint64_t>();
        add_surface_cell(tag, kind, degree, element_at);
      }
    } else {
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t element_at = (s_.skip_space(), s_.pos());
        const uint64_t tag = s_.unsigned_number("an element tag", true);
        ascii_node_tags(tag, *t);
        if (degree == 0)
          skip_element(tag);
        else
          add_surface_cell(tag, kind, degree, element_at);
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
  // Ascii: tag, type, number of tags, a node; binary: tag and a node (4 bytes each).
  s_.check_count(n, 8, "elements", header_at);
  check_budget(points_.size(), cells_.num_cells() + n, cells_.cell_nodes.size() + 3 * n, header_at);
  element_index_.allow_flat(2 * (cells_.num_cells() + n) + 1024);
  skipped_index_.allow_flat(2 * (skipped_elements_ + n) + 1024);
  if (binary_) {
    read_elements_22_binary(n);
    return;
  }
  for (uint64_t i = 0; i < n; ++i) {
    const std::size_t element_at = (s_.skip_space(), s_.pos());
    const uint64_t tag = s_.unsigned_number("an element tag", true);
    const int64_t type = s_.signed_number("the element type");
    const uint64_t ntags = s_.unsigned_number("the number of element tags");
    for (uint64_t k = 0; k < ntags; ++k)
      s_.signed_number("an element tag (physical, elementary, ...)");
    const bool type_fits = type > 0 && type <= std::numeric_limits<int>::max();
    const MshElementType *t = type_fits ? msh_element_type(static_cast<int>(type)) : nullptr;
    const int degree = t ? t->surface_degree() : 0;
    const CellKind kind = t ? t->surface_kind() : CellKind::LagrangeTriangle;
    if (!t || (t->dimension >= 2 && degree == 0))
      reject_element(type, t, tag, element_at);
    tags_.resize(static_cast<std::size_t>(t->nodes));
    ascii_node_tags(tag, *t);
    if (degree == 0)
      skip_element(tag);
    else
      add_surface_cell(tag, kind, degree, element_at);
  }
  expect_end("$EndElements");
  have_elements_ = true;
}

// Binary MSH 2.2: blocks of a header (type, number of elements, number of tags: 3 ints) and
// that many elements of the type: tag, tags, nodes (ints).
void MshReader::read_elements_22_binary(uint64_t total) {
  uint64_t seen = 0;
  while (seen < total) {
    const std::size_t block_at = s_.pos();
    s_.need(12, "an element block header");
    const auto type = s_.get_unchecked<int32_t>();
    const auto n = s_.get_unchecked<int32_t>();
    const auto ntags = s_.get_unchecked<int32_t>();
    if (n <= 0)
      s_.fail_at(block_at, "element block: " + str(int64_t{n}) + " elements");
    if (ntags < 0)
      s_.fail_at(block_at, "element block: " + str(int64_t{ntags}) + " element tags");
    if (static_cast<uint64_t>(n) > total - seen)
      s_.fail_at(block_at, "the element blocks hold more elements than the " + str(total) +
                               " the $Elements header announces");
    const MshElementType *t = type > 0 ? msh_element_type(type) : nullptr;
    const int degree = t ? t->surface_degree() : 0;
    const CellKind kind = t ? t->surface_kind() : CellKind::LagrangeTriangle;
    if (!t || (t->dimension >= 2 && degree == 0)) {
      const std::size_t first_at = s_.pos();
      reject_element(type, t, static_cast<uint64_t>(s_.get<int32_t>("an element tag")), first_at);
    }
    const auto nodes = static_cast<uint64_t>(t->nodes);
    const uint64_t record = 4 * (1 + static_cast<uint64_t>(ntags) + nodes);
    s_.check_count(static_cast<uint64_t>(n), record, "elements in the block", block_at);
    s_.need(record * static_cast<uint64_t>(n), "the element block");
    tags_.resize(nodes);
    for (int32_t i = 0; i < n; ++i) {
      const std::size_t element_at = s_.pos();
      const auto tag = s_.get_unchecked<int32_t>();
      if (tag <= 0)
        s_.fail_at(element_at, "element tag " + str(int64_t{tag}) + " (tags are positive)");
      s_.seek(s_.pos() + 4 * static_cast<std::size_t>(ntags));
      for (auto &node : tags_) {
        const auto v = s_.get_unchecked<int32_t>();
        node = v > 0 ? static_cast<uint64_t>(v) : 0; // 0: no such node (tags are positive)
      }
      if (degree == 0)
        skip_element(static_cast<uint64_t>(tag));
      else
        add_surface_cell(static_cast<uint64_t>(tag), kind, degree, element_at);
    }
    seen += static_cast<uint64_t>(n);
  }
  expect_end("$EndElements");
  have_elements_ = true;
}

void MshReader::read_data(std::size_t at, DataKind kind) {
  const std::string section = section_of(kind);
  if (!have_nodes_)
    s_.fail_at(at, section + " before any $Nodes section: the nodes must come first");
  if (kind != DataKind::Node && !have_elements_)
    s_.fail_at(at, section + " before any $Elements section: the elements must come first");
  // The header is ascii in binary files too: counts and tags one per line.
  auto count = [&](const char *what, const char *items) {
    const std::size_t count_at = (s_.skip_space(), s_.pos());
    const uint64_t n = s_.unsigned_number(what, true);
    s_.end_line(what);
    s_.check_count(n, 2, items, count_at);
    return n;
  };
  DataBlock b;
  b.kind = kind;
  b.at = at;
  const uint64_t nstrings = count("the number of string tags", "string tags");
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
      b.name = t;
    else if (i == 1 && kind == DataKind::ElementNode)
      b.scheme = t;
  }
  const uint64_t nreals = count("the number of real tags", "real tags");
  for (uint64_t i = 0; i < nreals; ++i) {
    const std::size_t time_at = (s_.skip_space(), s_.pos());
    const double v = s_.real_number("a real tag (time)", true);
    s_.end_line("a real tag");
    if (i == 0 && !std::isfinite(v))
      s_.fail_at(time_at, section + " '" + b.name + "': the time " + str(v) + " is not finite");
    if (i == 0)
      b.time = v;
  }
  const std::size_t ints_at = (s_.skip_space(), s_.pos());
  const uint64_t nints = count("the number of integer tags", "integer tags");
  if (nints < 3)
    s_.fail_at(ints_at, section + " '" + b.name + "' has " + str(nints) +
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
    s_.fail_at(ints_at, section + " '" + b.name + "' has " + str(components) + " components");
  if (values < 0)
    s_.fail_at(ints_at, section + " '" + b.name + "' has " + str(values) + " values");
  b.step = step;
  b.components = components;
  b.count = static_cast<uint64_t>(values);
  const auto comps = static_cast<uint64_t>(components);
  // The smallest record: a tag (and a node count) and the components of one value.
  const uint64_t record = kind == DataKind::ElementNode
                              ? (binary_ ? 8 + 8 * comps : 2 * (2 + comps))
                              : (binary_ ? 4 + 8 * comps : 2 * (1 + comps));
  s_.check_count(b.count, record, "values", ints_at);

  auto view =
      std::find_if(views_.begin(), views_.end(), [&](const View &v) { return v.name == b.name; });
  if (view == views_.end()) {
    views_.push_back(View{b.name, kind, components, at, {}, {}, 0, -1});
    view = views_.end() - 1;
  } else if (view->kind != kind) {
    s_.fail_at(at, section + " '" + b.name + "': the file gives a view of this name as " +
                       section_of(view->kind) + " too");
  }
  view->components = components;
  if (!b.scheme.empty() && view->scheme.empty()) {
    // Gmsh writes a view's scheme just before its data, under a name several views share: the
    // last one of that name so far is this block's.
    view->scheme = b.scheme;
    view->scheme_at = at;
    for (std::size_t i = schemes_.size(); i-- > 0;)
      if (schemes_[i].name == b.scheme) {
        view->scheme_index = static_cast<int64_t>(i);
        break;
      }
  }
  if (std::none_of(view->steps.begin(), view->steps.end(),
                   [tag = step](const FileFieldStep &s) { return s.tag == tag; }))
    view->steps.push_back(FileFieldStep{step, b.time});
  b.values_at = s_.pos();
  scan_values(b, false);
  blocks_.push_back(std::move(b));
  expect_end(kind == DataKind::Node          ? "$EndNodeData"
             : kind == DataKind::ElementNode ? "$EndElementNodeData"
                                             : "$EndElementData");
}

// One value of a node of element `element` (tag): the first is kept, the lowest and highest are
// remembered to check continuity.
void MshReader::merge_value(std::size_t node, double v, uint64_t element) {
  if (std::isnan(values_[node])) {
    values_[node] = lo_[node] = hi_[node] = v;
    lo_element_[node] = hi_element_[node] = element;
    return;
  }
  if (v < lo_[node]) {
    lo_[node] = v;
    lo_element_[node] = element;
  }
  if (v > hi_[node]) {
    hi_[node] = v;
    hi_element_[node] = element;
  }
}

void MshReader::scan_values(const DataBlock &b, bool collect) {
  const std::string what = std::string(section_of(b.kind)) + " '" + b.name + "'";
  const auto comps = static_cast<uint64_t>(b.components);
  const uint64_t n = b.count;
  // The value a node's components give: the one, the chosen component, or the magnitude.
  double comp[9];
  const bool vector = field_.component != FieldSelection::kScalar;
  auto combined = [&]() {
    if (field_.component >= 0)
      return comp[field_.component];
    if (!vector)
      return comp[0];
    double sum = 0;
    for (uint64_t k = 0; k < comps; ++k)
      sum += comp[k] * comp[k];
    return std::sqrt(sum);
  };
  auto finite = [&](double v, const std::string &whose, std::size_t value_at) {
    if (!std::isfinite(v))
      s_.fail_at(value_at, what + ": " + whose + " has a non-finite value (" + str(v) + ")");
    return v;
  };

  if (b.kind == DataKind::Node) {
    auto store = [&](uint64_t tag, double v, std::size_t value_at) {
      finite(v, "node " + str(tag), value_at);
      const int64_t node = node_index_.find(tag);
      if (node != TagIndex::none)
        values_[static_cast<std::size_t>(node)] = v;
    };
    const uint64_t record = binary_ ? 4 + 8 * comps : 0;
    if (binary_) {
      s_.need(record * n, "the $NodeData values");
      if (!collect) {
        s_.skip(record * n, "the $NodeData values");
        return;
      }
      for (uint64_t i = 0; i < n; ++i) {
        const std::size_t tag_at = s_.pos();
        const auto tag = s_.get_unchecked<int32_t>();
        if (tag <= 0)
          s_.fail_at(tag_at, what + ": node tag " + str(int64_t{tag}) + " is not positive");
        for (uint64_t k = 0; k < comps; ++k)
          comp[k] = s_.get_unchecked<double>();
        store(static_cast<uint64_t>(tag), combined(), tag_at + 4);
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
    return;
  }

  if (b.kind == DataKind::Element) { // never collected: parsed and dropped
    if (binary_) {
      s_.skip((4 + 8 * comps) * n, "the $ElementData values");
      return;
    }
    for (uint64_t i = 0; i < n; ++i) {
      s_.unsigned_number("an element tag", true);
      for (uint64_t k = 0; k < comps; ++k)
        s_.real_number("a value");
      s_.end_line(comps == 1 ? "the element's value" : "the element's values");
    }
    return;
  }

  // $ElementNodeData: per element, its tag, its number of nodes and the values at its nodes
  // (in Gmsh's order of the element's nodes).
  for (uint64_t i = 0; i < n; ++i) {
    const std::size_t element_at = binary_ ? s_.pos() : (s_.skip_space(), s_.pos());
    uint64_t tag, nodes;
    if (binary_) {
      s_.need(8, "an element's tag and number of nodes");
      const auto t = s_.get_unchecked<int32_t>();
      const auto k = s_.get_unchecked<int32_t>();
      if (t <= 0)
        s_.fail_at(element_at, what + ": element tag " + str(int64_t{t}) + " is not positive");
      if (k <= 0)
        s_.fail_at(element_at,
                   what + ": element " + str(int64_t{t}) + " has " + str(int64_t{k}) + " nodes");
      tag = static_cast<uint64_t>(t);
      nodes = static_cast<uint64_t>(k);
    } else {
      tag = s_.unsigned_number("an element tag", true);
      nodes = s_.unsigned_number("the element's number of nodes");
      if (nodes == 0)
        s_.fail_at(element_at, what + ": element " + str(tag) + " has 0 nodes");
    }
    s_.check_count(nodes, binary_ ? 8 * comps : 2 * comps, "element nodes with values", element_at);
    // The element's nodes (Gmsh order: gmsh_to_lattice maps them to the canonical order).
    const int64_t *cell_nodes = nullptr;
    const std::vector<int> *perm = nullptr;
    if (collect) {
      const int64_t cell = element_index_.find(tag);
      if (cell == TagIndex::none) {
        if (skipped_index_.find(tag) == TagIndex::none)
          s_.fail_at(element_at, what + " gives values for element " + str(tag) +
                                     ", which is not in $Elements");
      } else {
        const auto c = static_cast<std::size_t>(cell);
        const int degree = cells_.cell_degree[c];
        perm = &gmsh_to_canonical(cells_.kind(c), degree);
        if (nodes != perm->size())
          s_.fail_at(element_at, what + ": element " + str(tag) + " (a " +
                                     cell_kind_name(cells_.kind(c)) + " of degree " +
                                     str(int64_t{degree}) + ") has " + str(uint64_t{perm->size()}) +
                                     " nodes, the data give values at " + str(nodes));
        cell_nodes = cells_.cell_nodes.data() + cells_.cell_offsets[c];
      }
    }
    if (binary_) {
      s_.need(8 * comps * nodes, "the element's values");
      if (!cell_nodes) {
        s_.skip(8 * comps * nodes, "the element's values");
        continue;
      }
      for (uint64_t k = 0; k < nodes; ++k) {
        const std::size_t value_at = s_.pos();
        for (uint64_t c = 0; c < comps; ++c)
          comp[c] = s_.get_unchecked<double>();
        const auto node = static_cast<std::size_t>(cell_nodes[(*perm)[k]]);
        merge_value(node, finite(combined(), "element " + str(tag), value_at), tag);
      }
    } else {
      for (uint64_t k = 0; k < nodes; ++k) {
        const std::size_t value_at = (s_.line_ends(), s_.pos());
        for (uint64_t c = 0; c < comps; ++c)
          comp[c] = s_.real_number("a value");
        if (cell_nodes) {
          const auto node = static_cast<std::size_t>(cell_nodes[(*perm)[k]]);
          merge_value(node, finite(combined(), "element " + str(tag), value_at), tag);
        }
      }
      s_.end_line("the element's values");
    }
  }
}

std::string MshReader::available() const {
  std::string names;
  for (const auto &v : views_) {
    std::string notes;
    if (v.components != 1)
      notes = str(v.components) + " components";
    if (v.kind != DataKind::Node)
      notes += (notes.empty() ? "" : ", ") + std::string(section_of(v.kind));
    names += (names.empty() ? "" : ", ") + v.name + (notes.empty() ? "" : " (" + notes + ")");
  }
  return names;
}

std::string MshReader::step_list(const View &v) {
  std::string s = str(uint64_t{v.steps.size()}) + " time step" + (v.steps.size() == 1 ? "" : "s");
  std::string times;
  const std::size_t shown = std::min<std::size_t>(v.steps.size(), 12);
  for (std::size_t i = 0; i < shown; ++i)
    times += (i ? ", " : "") + (v.steps[i].time ? str(*v.steps[i].time) : std::string("none"));
  if (shown < v.steps.size())
    times += ", ...";
  return s + " (times " + times + ")";
}

void MshReader::choose_view() {
  const View *v = nullptr;
  const bool vector = field_.component != FieldSelection::kScalar;
  for (const auto &view : views_) {
    const bool fits = !scalar_.empty()
                          ? view.name == scalar_
                          : view.kind != DataKind::Element &&
                                (vector ? view.components > 1 : view.components == 1) &&
                                !is_bookkeeping_array(view.name);
    if (fits) {
      v = &view;
      break;
    }
  }
  if (!v) {
    if (views_.empty())
      fail_file("the file has no node data: it holds a mesh but no $NodeData or $ElementNodeData "
                "section with a scalar field (in Gmsh, add a view and write it after the mesh, "
                "e.g. gmsh.view.write(view, file, append=True))");
    if (!scalar_.empty())
      fail_file("no $NodeData or $ElementNodeData named '" + scalar_ +
                "' (available: " + available() + ")");
    fail_file("no scalar $NodeData or $ElementNodeData (available: " + available() + ")");
  }
  const std::string what = std::string(section_of(v->kind)) + " '" + v->name + "'";
  if (v->kind == DataKind::Element)
    s_.fail_at(v->at, what + " holds one value per element: a piecewise-constant field has no "
                             "contour tree of this kind (hoct needs values at the nodes: "
                             "$NodeData, or $ElementNodeData of a continuous field)");
  if (!v->scheme.empty()) { // values at the nodes only in the elements' own Lagrange basis
    std::string why = "the file defines no $InterpolationScheme of that name before it";
    const int degree =
        v->scheme_index < 0
            ? -1
            : nodal_lagrange_degree(schemes_[static_cast<std::size_t>(v->scheme_index)], &why);
    if (degree < 0)
      s_.fail_at(v->scheme_at, what + " names the interpolation scheme '" + v->scheme + "', and " +
                                   why +
                                   ": its values are coefficients of that basis, not values at "
                                   "the elements' nodes, which hoct needs");
  }

  // The time step.
  const std::size_t nsteps = v->steps.size();
  std::size_t k = 0;
  if (field_.time) {
    const double t = *field_.time;
    k = nsteps;
    for (std::size_t i = 0; i < nsteps && k == nsteps; ++i)
      if (v->steps[i].time && std::abs(*v->steps[i].time - t) <=
                                  1e-9 * std::max(std::abs(*v->steps[i].time), std::abs(t)))
        k = i;
    if (k == nsteps)
      fail_file("--time " + str(t) + ": " + what + " has no time step at that time (" +
                step_list(*v) + ")");
  } else {
    const int64_t n = static_cast<int64_t>(nsteps);
    const int64_t i = field_.step < 0 ? n + field_.step : field_.step;
    if (i < 0 || i >= n)
      fail_file("--step " + str(int64_t{field_.step}) + ": " + what + " has " + step_list(*v) +
                ": steps 0 to " + str(n - 1) + ", or -" + str(n) + " to -1 from the end");
    k = static_cast<std::size_t>(i);
  }
  const int64_t step = v->steps[k].tag;

  values_.assign(points_.size(), kNoValue);
  const bool element_nodes = v->kind == DataKind::ElementNode;
  if (element_nodes) {
    lo_.assign(points_.size(), 0);
    hi_.assign(points_.size(), 0);
    lo_element_.assign(points_.size(), 0);
    hi_element_.assign(points_.size(), 0);
  }
  bool first = true;
  for (const DataBlock &b : blocks_) {
    if (b.name != v->name || b.step != step)
      continue;
    if (first)
      chosen_at_ = b.at;
    first = false;
    if (!vector && b.components != 1)
      s_.fail_at(b.at, what + " has " + str(b.components) +
                           " components; a scalar field needs 1 (choose one with --component N, "
                           "or --component magnitude)");
    if (vector && b.components == 1)
      s_.fail_at(b.at, "--component: " + what + " has one component");
    if (field_.component >= b.components)
      s_.fail_at(b.at, "--component " + str(int64_t{field_.component}) + ": " + what + " has " +
                           str(b.components) + " components (0 to " + str(b.components - 1) + ")");
    s_.seek(b.values_at);
    scan_values(b, true);
  }
  if (element_nodes)
    check_continuity(what);
  chosen_ = v->name;
  chosen_what_ = what;
  if (nsteps > 1)
    chosen_detail_ = "(" + step_description(k, nsteps, v->steps[k].time) + ")";
}

// $ElementNodeData gives each element its own values: where elements sharing a node disagree
// by more than rounding (relative to the field's range), the field is discontinuous.
void MshReader::check_continuity(const std::string &what) const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::size_t worst = 0;
  double jump = -1;
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (std::isnan(values_[i]))
      continue;
    lo = std::min(lo, lo_[i]);
    hi = std::max(hi, hi_[i]);
    if (hi_[i] - lo_[i] > jump) {
      jump = hi_[i] - lo_[i];
      worst = i;
    }
  }
  if (jump < 0)
    return;
  const double range = hi - lo;
  const double tolerance = 1e-9 * range + 8 * std::numeric_limits<double>::epsilon() *
                                              std::max(std::abs(lo), std::abs(hi));
  if (jump > tolerance)
    s_.fail_at(chosen_at_, what + ": node " + str(node_tags_[worst]) + " has values " +
                               str(lo_[worst]) + " (element " + str(lo_element_[worst]) + ") and " +
                               str(hi_[worst]) + " (element " + str(hi_element_[worst]) +
                               "): the field is discontinuous there (largest jump " + str(jump) +
                               " of a range " + str(range) + "); hoct needs a continuous field");
}

void MshReader::fill_contents() const {
  if (!contents_)
    return;
  contents_->fields.clear();
  for (const auto &v : views_)
    contents_->fields.push_back(FileField{v.name,
                                          v.kind == DataKind::Node          ? "node data"
                                          : v.kind == DataKind::ElementNode ? "element-node data"
                                                                            : "element data",
                                          v.components, v.steps});
}

MeshInput MshReader::finish() {
  if (!have_nodes_)
    fail_file("no $Nodes section");
  if (!have_elements_)
    fail_file("no $Elements section");
  if (cells_.num_cells() == 0)
    fail_file("no triangles in $Elements (" + str(skipped_elements_) +
              " point and line elements skipped)");
  fill_contents();
  choose_view();

  // Every node of every triangle needs a value; the nodes used are kept, in file order.
  values_.resize(points_.size(), kNoValue);
  std::vector<int64_t> renumber(points_.size(), -1);
  for (std::size_t c = 0; c < cells_.num_cells(); ++c)
    for (auto k = cells_.cell_offsets[c]; k < cells_.cell_offsets[c + 1]; ++k) {
      const auto node = static_cast<std::size_t>(cells_.cell_nodes[static_cast<std::size_t>(k)]);
      if (std::isnan(values_[node]))
        s_.fail_at(chosen_at_, chosen_what_ + " has no value for node " + str(node_tags_[node]) +
                                   " (of element " + str(cell_tags_[c]) + ")");
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
  m.field_detail = chosen_detail_;
  m.source = s_.path();
  return m;
}

} // namespace

MeshInput read_msh(const std::string &path, const FieldSelection &field, const ReadLimits &limits,
                   FileContents *contents) {
  return MshReader(path, read_whole_file(path), field, limits, contents).read();
}

MeshInput read_msh_buffer(std::string bytes, const std::string &name, const FieldSelection &field,
                          const ReadLimits &limits, FileContents *contents) {
  return MshReader(name, std::move(bytes), field, limits, contents).read();
}

} // namespace hoct
