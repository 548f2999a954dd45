#include "io/msh_reader.hpp"

#include "error.hpp"
#include "poly/lagrange_node_order.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

namespace hoct {
namespace {

// Complete triangles of Gmsh: element type -> order.
int triangle_order(int type) {
  switch (type) {
  case 2:
    return 1;
  case 9:
    return 2;
  case 21:
    return 3;
  case 23:
    return 4;
  case 25:
    return 5;
  case 42:
    return 6;
  case 43:
    return 7;
  case 44:
    return 8;
  case 45:
    return 9;
  case 46:
    return 10;
  default:
    return 0;
  }
}
bool incomplete_triangle(int type) {
  return type == 20 || type == 22 || type == 24 || (type >= 52 && type <= 55);
}
// Number of nodes of an element type we skip (points and lines), or -1 if unknown.
int skipped_node_count(int type) {
  switch (type) {
  case 15:
    return 1;
  case 1:
    return 2;
  case 8:
    return 3;
  case 26:
    return 4;
  case 27:
    return 5;
  case 28:
    return 6;
  default:
    return (type >= 62 && type <= 70) ? type - 55 : -1; // lines of order 6..14
  }
}

class MshFile {
public:
  MshFile(std::string path, std::string scalar)
      : path_(std::move(path)), scalar_(std::move(scalar)) {}
  MeshInput read();

private:
  [[noreturn]] void fail(const std::string &what) const {
    std::string where;
    if (binary_section_)
      where = " (byte " + std::to_string(pos_) + ")";
    else
      where = ":" + std::to_string(line_at(pos_));
    throw InputError(path_ + where + ": " + what);
  }
  std::size_t line_at(std::size_t pos) const {
    return 1 + static_cast<std::size_t>(
                   std::count(data_.begin(), data_.begin() + std::min(pos, data_.size()), '\n'));
  }
  // ASCII tokens.
  std::string_view token(const char *what) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      ++pos_;
    if (pos_ >= data_.size())
      fail(std::string("unexpected end of file (expected ") + what + ")");
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_])))
      ++pos_;
    return std::string_view(data_).substr(start, pos_ - start);
  }
  long long integer(const char *what) {
    const std::size_t at = pos_;
    const auto t = token(what);
    long long v;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size()) {
      pos_ = at;
      fail(std::string("expected an integer (") + what + "), got '" + std::string(t) + "'");
    }
    return v;
  }
  double real(const char *what) {
    const std::size_t at = pos_;
    const auto t = token(what);
    double v;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size()) {
      pos_ = at;
      fail(std::string("expected a number (") + what + "), got '" + std::string(t) + "'");
    }
    return v;
  }
  // Binary values.
  template <class T> T bin(const char *what) {
    if (pos_ + sizeof(T) > data_.size())
      fail(std::string("unexpected end of file in binary data (") + what + ")");
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  long long count(const char *what) { // size_t in binary, integer in ascii; >= 0
    long long v = binary_ ? static_cast<long long>(bin<uint64_t>(what)) : integer(what);
    if (v < 0 || static_cast<unsigned long long>(v) > data_.size())
      fail(std::string("implausible ") + what + " " + std::to_string(v) +
           " (more than the file can hold)");
    return v;
  }
  int small_int(const char *what) {
    return binary_ ? bin<int32_t>(what) : static_cast<int>(integer(what));
  }
  long long tag(const char *what) {
    const long long v = binary_ ? static_cast<long long>(bin<uint64_t>(what)) : integer(what);
    if (v <= 0)
      fail(std::string("invalid ") + what + " " + std::to_string(v) + " (tags are positive)");
    return v;
  }
  double coord(const char *what) { return binary_ ? bin<double>(what) : real(what); }
  void expect_line(const std::string &marker) {
    const auto t = token(marker.c_str());
    if (t != marker)
      fail("expected " + marker + ", got '" + std::string(t).substr(0, 40) + "'");
  }
  // Skips to just after "\n$End<name>".
  void skip_section(const std::string &name) {
    const std::string end = "$End" + name;
    const std::size_t at = data_.find(end, pos_);
    if (at == std::string::npos)
      fail("section $" + name + " has no " + end);
    pos_ = at + end.size();
  }
  // Gmsh's own view.write(append=True) repeats the whole mesh before each view: a node or
  // element seen again must be identical, and is then ignored.
  void add_node(long long tag, const Vec3 &p) {
    const auto [it, fresh] = node_index_.emplace(tag, static_cast<int64_t>(points_.size()));
    if (!fresh) {
      if (points_[it->second] != p)
        fail("node tag " + std::to_string(tag) + " appears twice with different coordinates");
      return;
    }
    points_.push_back(p);
    node_tag_.push_back(tag);
  }
  void add_triangle(long long etag, int order, const long long *nodes, int n) {
    const auto [it, fresh] = element_index_.emplace(etag, tri_degree_.size());
    if (!fresh) {
      const std::size_t e = it->second;
      if (tri_degree_[e] != order ||
          !std::equal(nodes, nodes + n,
                      tri_nodes_.begin() + static_cast<std::ptrdiff_t>(tri_offset_[e])))
        fail("element tag " + std::to_string(etag) + " appears twice with different nodes");
      return;
    }
    tri_degree_.push_back(order);
    tri_tag_.push_back(etag);
    tri_offset_.push_back(tri_nodes_.size());
    tri_nodes_.insert(tri_nodes_.end(), nodes, nodes + n);
  }
  void start_binary_section();
  void read_format();
  void read_nodes_41();
  void read_elements_41();
  void read_nodes_22();
  void read_elements_22();
  void read_node_data();

  std::string path_, scalar_;
  std::string data_;
  std::size_t pos_ = 0;
  bool binary_ = false, binary_section_ = false;
  int version_ = 41;
  // Nodes by tag.
  std::unordered_map<long long, int64_t> node_index_;
  std::vector<Vec3> points_;
  std::vector<long long> node_tag_;
  // Triangles: degree, element tag, node tags in Gmsh order.
  std::vector<int> tri_degree_;
  std::vector<long long> tri_tag_;
  std::vector<long long> tri_nodes_;
  std::vector<std::size_t> tri_offset_;
  std::unordered_map<long long, std::size_t> element_index_;
  long long skipped_elements_ = 0;
  // Node data views (name, tag -> value), in file order.
  std::vector<std::pair<std::string, std::unordered_map<long long, double>>> views_;
  bool have_nodes_ = false, have_elements_ = false;
};

void MshFile::read_format() {
  const auto v = token("the format version");
  if (v == "4.1")
    version_ = 41;
  else if (v == "2.2")
    version_ = 22;
  else
    fail("MSH format version " + std::string(v) + " is not supported (4.1, or 2.2 ascii)");
  const long long type = integer("the file type");
  const long long size = integer("the data size");
  if (type != 0 && type != 1)
    fail("unknown file type " + std::to_string(type) + " (0 ascii, 1 binary)");
  if (size != 8)
    fail("data size " + std::to_string(size) + " is not supported (8)");
  binary_ = type == 1;
  if (binary_ && version_ != 41)
    fail("binary MSH 2.2 is not supported (write MSH 4.1 or ascii)");
  if (binary_) {
    // One int 1 after a newline, to check endianness.
    while (pos_ < data_.size() && data_[pos_] != '\n')
      ++pos_;
    ++pos_;
    binary_section_ = true;
    const int32_t one = bin<int32_t>("the endianness check");
    binary_section_ = false;
    if (one != 1)
      fail("binary file of the other endianness (not supported)");
  }
  expect_line("$EndMeshFormat");
}

void MshFile::start_binary_section() {
  // Binary data starts after the newline that ends the section's header line.
  if (!binary_)
    return;
  while (pos_ < data_.size() && data_[pos_] != '\n')
    ++pos_;
  ++pos_;
  binary_section_ = true;
}

void MshFile::read_nodes_41() {
  start_binary_section();
  const long long blocks = count("number of entity blocks");
  const long long total = count("number of nodes");
  count("minimum node tag");
  count("maximum node tag");
  points_.reserve(points_.size() + static_cast<std::size_t>(total));
  long long read_in_section = 0;
  std::vector<long long> tags;
  for (long long b = 0; b < blocks; ++b) {
    const int dim = small_int("entity dimension");
    small_int("entity tag");
    const int parametric = small_int("parametric flag");
    const long long n = count("number of nodes in the block");
    if (dim < 0 || dim > 3 || (parametric != 0 && parametric != 1))
      fail("bad node block header (dimension " + std::to_string(dim) + ", parametric " +
           std::to_string(parametric) + ")");
    tags.resize(static_cast<std::size_t>(n));
    for (long long i = 0; i < n; ++i)
      tags[i] = tag("node tag");
    const int extra = parametric ? dim : 0;
    for (long long i = 0; i < n; ++i) {
      Vec3 p;
      for (int k = 0; k < 3; ++k)
        p[k] = coord("node coordinate");
      for (int k = 0; k < extra; ++k)
        coord("parametric coordinate");
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        fail("node " + std::to_string(tags[i]) + " has a NaN or infinite coordinate");
      add_node(tags[i], p);
    }
    read_in_section += n;
  }
  if (read_in_section != total)
    fail("$Nodes announces " + std::to_string(total) + " nodes but holds " +
         std::to_string(read_in_section));
  binary_section_ = false;
  expect_line("$EndNodes");
  have_nodes_ = true;
}

void MshFile::read_elements_41() {
  start_binary_section();
  const long long blocks = count("number of entity blocks");
  count("number of elements");
  count("minimum element tag");
  count("maximum element tag");
  for (long long b = 0; b < blocks; ++b) {
    const int dim = small_int("entity dimension");
    small_int("entity tag");
    const int type = small_int("element type");
    const long long n = count("number of elements in the block");
    int order = triangle_order(type), nodes;
    if (order > 0) {
      nodes = (order + 1) * (order + 2) / 2;
    } else if (incomplete_triangle(type)) {
      fail("incomplete (serendipity) triangle type " + std::to_string(type) +
           " is not supported: hoct needs complete Lagrange triangles");
    } else if (dim <= 1 && (nodes = skipped_node_count(type)) > 0) {
      // points and lines: skipped
    } else {
      fail("element type " + std::to_string(type) + " (dimension " + std::to_string(dim) +
           ") is not a triangle; hoct reads triangle meshes");
    }
    std::vector<long long> en(static_cast<std::size_t>(nodes));
    for (long long i = 0; i < n; ++i) {
      const long long etag = tag("element tag");
      for (int k = 0; k < nodes; ++k)
        en[k] = tag("node tag");
      if (order == 0)
        ++skipped_elements_;
      else
        add_triangle(etag, order, en.data(), nodes);
    }
  }
  binary_section_ = false;
  expect_line("$EndElements");
  have_elements_ = true;
}

void MshFile::read_nodes_22() {
  const long long n = count("number of nodes");
  for (long long i = 0; i < n; ++i) {
    const long long t = tag("node tag");
    Vec3 p;
    for (int k = 0; k < 3; ++k)
      p[k] = real("node coordinate");
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail("node " + std::to_string(t) + " has a NaN or infinite coordinate");
    add_node(t, p);
  }
  expect_line("$EndNodes");
  have_nodes_ = true;
}

void MshFile::read_elements_22() {
  const long long n = count("number of elements");
  for (long long i = 0; i < n; ++i) {
    const long long etag = tag("element tag");
    const int type = static_cast<int>(integer("element type"));
    const long long ntags = integer("number of element tags");
    if (ntags < 0 || ntags > 100)
      fail("implausible number of element tags " + std::to_string(ntags));
    for (long long k = 0; k < ntags; ++k)
      integer("element tag value");
    const int order = triangle_order(type);
    int nodes;
    if (order > 0)
      nodes = (order + 1) * (order + 2) / 2;
    else if (incomplete_triangle(type))
      fail("incomplete (serendipity) triangle type " + std::to_string(type) + " is not supported");
    else if ((nodes = skipped_node_count(type)) < 0)
      fail("element " + std::to_string(etag) + " has type " + std::to_string(type) +
           ", which is not a triangle");
    std::vector<long long> en(static_cast<std::size_t>(nodes));
    for (int k = 0; k < nodes; ++k)
      en[k] = tag("node tag");
    if (order == 0)
      ++skipped_elements_;
    else
      add_triangle(etag, order, en.data(), nodes);
  }
  expect_line("$EndElements");
  have_elements_ = true;
}

void MshFile::read_node_data() {
  // Headers are ascii in both modes.
  const long long nstr = integer("number of string tags");
  if (nstr < 0 || nstr > 1000)
    fail("implausible number of string tags " + std::to_string(nstr));
  std::string name;
  for (long long i = 0; i < nstr; ++i) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      ++pos_;
    std::string s;
    if (pos_ < data_.size() && data_[pos_] == '"') {
      const std::size_t end = data_.find('"', pos_ + 1);
      if (end == std::string::npos)
        fail("unterminated string tag");
      s = data_.substr(pos_ + 1, end - pos_ - 1);
      pos_ = end + 1;
    } else {
      s = std::string(token("string tag"));
    }
    if (i == 0)
      name = s;
  }
  const long long nreal = integer("number of real tags");
  if (nreal < 0 || nreal > 1000)
    fail("implausible number of real tags");
  for (long long i = 0; i < nreal; ++i)
    real("real tag");
  const long long nint = integer("number of integer tags");
  if (nint < 3 || nint > 1000)
    fail("$NodeData needs at least 3 integer tags (time step, components, count), got " +
         std::to_string(nint));
  long long ints[4] = {0, 0, 0, 0};
  for (long long i = 0; i < nint; ++i) {
    const long long v = integer("integer tag");
    if (i < 4)
      ints[i] = v;
  }
  const long long comps = ints[1], n = ints[2];
  if (comps < 1 || comps > 9)
    fail("$NodeData '" + name + "' has " + std::to_string(comps) + " components");
  if (n < 0 || static_cast<unsigned long long>(n) > data_.size())
    fail("$NodeData '" + name + "' announces an implausible " + std::to_string(n) + " values");
  std::unordered_map<long long, double> values;
  values.reserve(static_cast<std::size_t>(n));
  start_binary_section();
  for (long long i = 0; i < n; ++i) {
    const long long t = binary_ ? bin<int32_t>("node tag") : integer("node tag");
    double v = binary_ ? bin<double>("value") : real("value");
    for (long long k = 1; k < comps; ++k)
      (void)(binary_ ? bin<double>("value") : real("value"));
    if (comps == 1 && !std::isfinite(v))
      fail("$NodeData '" + name + "': node " + std::to_string(t) + " has a non-finite value");
    values[t] = comps == 1 ? v : NAN;
  }
  binary_section_ = false;
  expect_line("$EndNodeData");
  if (comps != 1 && name == scalar_)
    fail("$NodeData '" + name + "' has " + std::to_string(comps) +
         " components; a scalar field needs 1");
  if (comps != 1)
    return;
  // A later view of the same name (a later time step) replaces the earlier one.
  for (auto &v : views_)
    if (v.first == name) {
      v.second = std::move(values);
      return;
    }
  views_.emplace_back(name, std::move(values));
}

MeshInput MshFile::read() {
  std::ifstream in(path_, std::ios::binary);
  if (!in)
    throw InputError(path_ + ": cannot open (" + std::strerror(errno) + ")");
  std::ostringstream ss;
  ss << in.rdbuf();
  data_ = ss.str();
  if (data_.empty())
    throw InputError(path_ + ": the file is empty");
  bool have_format = false;
  while (true) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      ++pos_;
    if (pos_ >= data_.size())
      break;
    const auto t = token("a section");
    if (t.empty() || t[0] != '$')
      fail("expected a section like $Nodes, got '" + std::string(t).substr(0, 40) + "'");
    const std::string section(t.substr(1));
    if (section == "MeshFormat") {
      read_format();
      have_format = true;
      continue;
    }
    if (!have_format)
      fail("the file does not start with $MeshFormat (not a Gmsh .msh file?)");
    if (section == "Nodes")
      version_ == 41 ? read_nodes_41() : read_nodes_22();
    else if (section == "Elements")
      version_ == 41 ? read_elements_41() : read_elements_22();
    else if (section == "NodeData")
      read_node_data();
    else
      skip_section(section);
  }
  if (!have_format)
    throw InputError(path_ + ": not a Gmsh .msh file (no $MeshFormat)");
  if (!have_nodes_)
    throw InputError(path_ + ": no $Nodes section");
  if (!have_elements_)
    throw InputError(path_ + ": no $Elements section");
  if (tri_degree_.empty())
    throw InputError(path_ + ": no triangle elements (" + std::to_string(skipped_elements_) +
                     " points or lines only)");
  if (views_.empty())
    throw InputError(path_ + ": no scalar $NodeData: the file holds a mesh but no field "
                             "(export a node-data view with the mesh)");
  const std::unordered_map<long long, double> *view = &views_.front().second;
  std::string field = views_.front().first;
  if (!scalar_.empty()) {
    view = nullptr;
    std::string names;
    for (const auto &v : views_) {
      names += (names.empty() ? "" : ", ") + v.first;
      if (v.first == scalar_) {
        view = &v.second;
        field = v.first;
      }
    }
    if (!view)
      throw InputError(path_ + ": no $NodeData named '" + scalar_ + "' (available: " + names + ")");
  }
  // Keep only the nodes the triangles use, in first-use order.
  MeshInput m;
  m.source = path_;
  m.field_name = field;
  std::unordered_map<long long, int64_t> used;
  std::vector<int64_t> nodes;
  for (std::size_t e = 0; e < tri_degree_.size(); ++e) {
    std::size_t at = tri_offset_[e];
    const int d = tri_degree_[e];
    const auto &perm = node_order_to_lattice(NodeOrdering::Gmsh, d);
    nodes.assign(perm.size(), -1);
    for (std::size_t i = 0; i < perm.size(); ++i) {
      const long long t = tri_nodes_[at++];
      auto it = used.find(t);
      if (it == used.end()) {
        const auto pn = node_index_.find(t);
        if (pn == node_index_.end())
          throw InputError(path_ + ": element " + std::to_string(tri_tag_[e]) + " refers to node " +
                           std::to_string(t) + ", which is not in $Nodes");
        const auto pv = view->find(t);
        if (pv == view->end())
          throw InputError(path_ + ": node " + std::to_string(t) + " (of element " +
                           std::to_string(tri_tag_[e]) + ") has no value in $NodeData '" + field +
                           "'");
        it = used.emplace(t, static_cast<int64_t>(m.points.size())).first;
        m.points.push_back(points_[pn->second]);
        m.values.push_back(pv->second);
      }
      nodes[perm[i]] = it->second;
    }
    m.add_cell(d, nodes.data());
  }
  return m;
}

} // namespace

MeshInput read_msh(const std::string &path, const std::string &scalar) {
  return MshFile(path, scalar).read();
}

} // namespace hoct
