// Reader for Gmsh's parsed post-processing format (.pos), see pos_reader.hpp.
//
// The grammar read (Gmsh's own parser accepts much more: any script command and expressions):
//   file      := { view }
//   view      := "View" STRING "{" { statement } "}" [";"]
//   statement := TYPE "(" numbers ")" "{" numbers "}" ";"      (SP SL SL2 ST ST2 ST3)
//              | "TIME" "{" numbers "}" ";"
//              | ("T2" | "T3") "(" numbers ")" "{" strings "}" ";"  (skipped)
// with // and /* */ comments. Coordinates are x, y, z per node, nodes in Gmsh's order of the
// element (ST2: corners, then the midpoints of edges 01, 12, 20, as MSH type 9; ST3 as type 21);
// values are the nodes' values at step 0, then at step 1, ...
#include "io/pos_reader.hpp"

#include "io/msh_scanner.hpp"
#include "mesh/duplicate_points.hpp"
#include "poly/lagrange_node_order.hpp"
#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <algorithm>
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

std::string str(uint64_t v) { return std::to_string(v); }
std::string str(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string read_whole_file(const std::string &path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a .pos file");
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

// Gmsh's list types: the letter of the value kind (S, V, T) and of the element, its order.
struct PosType {
  const char *name;
  const char *what;
  int nodes;  // 0: not read
  int degree; // of a scalar triangle, else 0
};
const PosType kTypes[] = {
    {"ST", "scalar triangle", 3, 1},
    {"ST2", "scalar triangle of degree 2", 6, 2},
    {"ST3", "scalar triangle of degree 3", 10, 3},
    {"SP", "scalar point", 1, 0},
    {"SL", "scalar line", 2, 0},
    {"SL2", "scalar line of degree 2", 3, 0},
};
const char *const kRefused[][2] = {
    {"VP", "vector point"},       {"TP", "tensor point"},        {"VL", "vector line"},
    {"TL", "tensor line"},        {"VT", "vector triangle"},     {"TT", "tensor triangle"},
    {"VT2", "vector triangle"},   {"TT2", "tensor triangle"},    {"SQ", "scalar quadrangle"},
    {"VQ", "vector quadrangle"},  {"TQ", "tensor quadrangle"},   {"SQ2", "scalar quadrangle"},
    {"VQ2", "vector quadrangle"}, {"SS", "scalar tetrahedron"},  {"VS", "vector tetrahedron"},
    {"TS", "tensor tetrahedron"}, {"SS2", "scalar tetrahedron"}, {"SH", "scalar hexahedron"},
    {"VH", "vector hexahedron"},  {"TH", "tensor hexahedron"},   {"SH2", "scalar hexahedron"},
    {"SI", "scalar prism"},       {"VI", "vector prism"},        {"TI", "tensor prism"},
    {"SI2", "scalar prism"},      {"SY", "scalar pyramid"},      {"VY", "vector pyramid"},
    {"TY", "tensor pyramid"},     {"SY2", "scalar pyramid"},     {"VL2", "vector line"},
    {"TL2", "tensor line"},
};

struct PosView {
  std::string name;
  std::size_t at = 0;
  std::vector<double> times;
  std::size_t times_at = 0;
  // Triangles: degree, first coordinate and value in the arrays below, and where they are.
  std::vector<uint8_t> degree;
  std::vector<std::size_t> coord_begin, value_begin, element_at;
  std::vector<double> coords, values;
  int64_t steps = -1; // values per node, the same for every element
  uint64_t skipped = 0;
};

class PosReader {
public:
  PosReader(const std::string &path, std::string data, FieldSelection field,
            const ReadLimits &limits, FileContents *contents)
      : s_(path, std::move(data)), field_(std::move(field)), limits_(limits), contents_(contents) {}
  MeshInput read();

private:
  // ---- tokens ----
  void skip_space(); // whitespace and comments
  bool at_end() {
    skip_space();
    return pos_ >= d().size();
  }
  std::string_view d() const { return s_.data(); }
  std::string_view identifier();
  void expect(char c, const char *after);
  bool accept(char c) {
    skip_space();
    if (pos_ < d().size() && d()[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  std::string string_literal(const char *what);
  double number(const char *what);
  // Numbers separated by commas up to `close`; appended to `out`.
  void numbers(char close, std::vector<double> &out, const char *what);
  std::string token_here();

  void read_view(std::size_t at);
  MeshInput build(const PosView &v);

  MshScanner s_; // for the data and the places of messages
  std::size_t pos_ = 0;
  FieldSelection field_;
  ReadLimits limits_;
  FileContents *contents_;
  std::vector<PosView> views_;
};

void PosReader::skip_space() {
  const std::string_view t = d();
  while (pos_ < t.size()) {
    const char c = t[pos_];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++pos_;
    } else if (c == '/' && pos_ + 1 < t.size() && t[pos_ + 1] == '/') {
      const std::size_t e = t.find('\n', pos_);
      pos_ = e == std::string_view::npos ? t.size() : e + 1;
    } else if (c == '/' && pos_ + 1 < t.size() && t[pos_ + 1] == '*') {
      const std::size_t e = t.find("*/", pos_ + 2);
      if (e == std::string_view::npos)
        s_.fail_at(pos_, "a /* comment is not closed");
      pos_ = e + 2;
    } else {
      return;
    }
  }
}

std::string PosReader::token_here() {
  skip_space();
  if (pos_ >= d().size())
    return "the end of the file";
  std::size_t e = pos_;
  while (e < d().size() && !std::isspace(static_cast<unsigned char>(d()[e])) && e - pos_ < 20)
    ++e;
  return MshScanner::quote(d().substr(pos_, std::max<std::size_t>(e - pos_, 1)));
}

std::string_view PosReader::identifier() {
  skip_space();
  const std::size_t start = pos_;
  while (pos_ < d().size() && (std::isalnum(static_cast<unsigned char>(d()[pos_])) ||
                               d()[pos_] == '_' || d()[pos_] == '.'))
    ++pos_;
  return d().substr(start, pos_ - start);
}

void PosReader::expect(char c, const char *after) {
  if (!accept(c))
    s_.fail_at(pos_, std::string("expected '") + c + "' " + after + ", got " + token_here());
}

std::string PosReader::string_literal(const char *what) {
  skip_space();
  if (pos_ >= d().size() || d()[pos_] != '"')
    s_.fail_at(pos_, std::string("expected ") + what + " (a \"string\"), got " + token_here());
  const std::size_t start = pos_;
  const std::size_t e = d().find('"', pos_ + 1);
  if (e == std::string_view::npos)
    s_.fail_at(start, "unterminated string " + MshScanner::quote(d().substr(start)));
  pos_ = e + 1;
  return std::string(d().substr(start + 1, e - start - 1));
}

double PosReader::number(const char *what) {
  skip_space();
  const std::size_t start = pos_;
  std::size_t e = pos_;
  while (e < d().size() && (std::isalnum(static_cast<unsigned char>(d()[e])) || d()[e] == '.' ||
                            d()[e] == '-' || d()[e] == '+'))
    ++e;
  std::string_view t = d().substr(start, e - start);
  const std::string_view digits = t.size() > 1 && t[0] == '+' && t[1] != '-' ? t.substr(1) : t;
  double v = 0;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (t.empty() || r.ec != std::errc() || r.ptr != digits.data() + digits.size())
    s_.fail_at(start, std::string("expected ") + what + " (a number; hoct does not evaluate " +
                          "expressions), got " + token_here());
  pos_ = e;
  if (!std::isfinite(v))
    s_.fail_at(start, std::string(what) + " " + MshScanner::quote(t) + " is not finite");
  return v;
}

void PosReader::numbers(char close, std::vector<double> &out, const char *what) {
  if (accept(close))
    return;
  for (;;) {
    out.push_back(number(what));
    if (accept(close))
      return;
    if (!accept(','))
      s_.fail_at(pos_, std::string("expected ',' or '") + close + "' after " + what + ", got " +
                           token_here());
  }
}

MeshInput PosReader::read() {
  while (!at_end()) {
    const std::size_t at = pos_;
    const std::string_view word = identifier();
    if (word != "View")
      s_.fail_at(at, "expected a View, got " +
                         (word.empty() ? token_here() : MshScanner::quote(word)) +
                         " (hoct reads .pos files of views in Gmsh's parsed format, "
                         "not Gmsh script commands)");
    read_view(at);
  }
  if (contents_) {
    contents_->fields.clear();
    for (const PosView &v : views_) {
      FileField f{v.name, "element-node data", 1, {}};
      for (int64_t k = 0; k < std::max<int64_t>(v.steps, 1); ++k)
        f.steps.push_back(
            FileFieldStep{k, static_cast<std::size_t>(k) < v.times.size()
                                 ? std::optional<double>(v.times[static_cast<std::size_t>(k)])
                                 : std::nullopt});
      contents_->fields.push_back(std::move(f));
    }
  }
  if (views_.empty())
    throw InputError(s_.path() + ": the file has no View");
  const PosView *chosen = nullptr;
  for (const PosView &v : views_)
    if (field_.name.empty() ? !v.degree.empty() : v.name == field_.name) {
      chosen = &v;
      break;
    }
  if (!chosen) {
    std::string names;
    for (const PosView &v : views_)
      names +=
          (names.empty() ? "" : ", ") + v.name + (v.degree.empty() ? " (no scalar triangles)" : "");
    if (!field_.name.empty())
      throw InputError(s_.path() + ": no View named '" + field_.name + "' (available: " + names +
                       ")");
    throw InputError(s_.path() +
                     ": no View holds scalar triangles (ST, ST2, ST3) (views: " + names + ")");
  }
  if (field_.component != FieldSelection::kScalar)
    throw InputError(s_.path() + ": --component: View '" + chosen->name +
                     "' holds scalar values (one component)");
  return build(*chosen);
}

void PosReader::read_view(std::size_t at) {
  PosView v;
  v.at = at;
  v.name = string_literal("the view's name");
  expect('{', "after the view's name");
  std::vector<double> numbers_here;
  while (!accept('}')) {
    const std::size_t element_at = (skip_space(), pos_);
    if (pos_ >= d().size())
      s_.fail_at(at, "View '" + v.name + "' has no closing '}'");
    const std::string word(identifier());
    if (word.empty())
      s_.fail_at(element_at, "expected an element type such as ST, got " + token_here());
    if (word == "TIME") {
      v.times.clear();
      v.times_at = element_at;
      expect('{', "after TIME");
      numbers('}', v.times, "a time");
      expect(';', "after TIME{...}");
      continue;
    }
    if (word == "T2" || word == "T3") { // text annotations
      numbers_here.clear();
      expect('(', ("after " + word).c_str());
      numbers(')', numbers_here, "a coordinate");
      expect('{', "after the text's position");
      if (!accept('}'))
        for (;;) {
          string_literal("a text");
          if (accept('}'))
            break;
          expect(',', "between texts");
        }
      expect(';', "after the text");
      continue;
    }
    const PosType *type = nullptr;
    for (const PosType &t : kTypes)
      if (word == t.name)
        type = &t;
    if (!type) {
      for (const auto &r : kRefused)
        if (word == r[0])
          s_.fail_at(element_at, "View '" + v.name + "': " + word + " (" + r[1] +
                                     ") is not read: hoct reads scalar triangles (ST, ST2, ST3)");
      s_.fail_at(element_at, "View '" + v.name + "': unknown element type " +
                                 MshScanner::quote(word) + " (hoct reads ST, ST2, ST3)");
    }
    const std::size_t coords_begin = v.coords.size(), values_begin = v.values.size();
    std::vector<double> &coords = type->degree ? v.coords : numbers_here;
    std::vector<double> &values = type->degree ? v.values : numbers_here;
    numbers_here.clear();
    expect('(', ("after " + word).c_str());
    numbers(')', coords, "a coordinate");
    const std::size_t ncoords = coords.size() - (type->degree ? coords_begin : 0);
    if (ncoords != 3 * static_cast<std::size_t>(type->nodes))
      s_.fail_at(element_at, "View '" + v.name + "': " + word + " has " + str(uint64_t{ncoords}) +
                                 " coordinates, expected " + str(uint64_t(3 * type->nodes)) +
                                 " (x, y, z of " + str(uint64_t(type->nodes)) + " nodes)");
    const std::size_t before = values.size();
    expect('{', "after the element's coordinates");
    numbers('}', values, "a value");
    expect(';', "after the element's values");
    const std::size_t nvalues = values.size() - before;
    const auto nodes = static_cast<std::size_t>(type->nodes);
    if (nvalues == 0 || nvalues % nodes != 0)
      s_.fail_at(element_at, "View '" + v.name + "': " + word + " has " + str(uint64_t{nvalues}) +
                                 " values, not a multiple of its " + str(uint64_t{nodes}) +
                                 " nodes (one value per node and time step)");
    const auto steps = static_cast<int64_t>(nvalues / nodes);
    if (v.steps >= 0 && steps != v.steps)
      s_.fail_at(element_at, "View '" + v.name + "': " + word + " has values for " +
                                 str(uint64_t(steps)) + " time steps, the elements before it for " +
                                 str(uint64_t(v.steps)));
    v.steps = steps;
    if (!type->degree) {
      ++v.skipped;
      continue;
    }
    v.degree.push_back(static_cast<uint8_t>(type->degree));
    v.coord_begin.push_back(coords_begin);
    v.value_begin.push_back(values_begin);
    v.element_at.push_back(element_at);
    if (limits_.max_memory_bytes) {
      const uint64_t cells = v.degree.size(), points = v.coords.size() / 3;
      if (estimate_memory_bytes(points, cells, points) > limits_.max_memory_bytes)
        check_memory(limits_, points, cells, points, s_.where(element_at));
    }
  }
  accept(';');
  if (!v.times.empty() && v.steps >= 0 && static_cast<int64_t>(v.times.size()) != v.steps)
    s_.fail_at(v.times_at, "View '" + v.name + "': TIME gives " + str(uint64_t{v.times.size()}) +
                               " times for " + str(uint64_t(v.steps)) + " time steps");
  views_.push_back(std::move(v));
}

MeshInput PosReader::build(const PosView &v) {
  const std::string what = "View '" + v.name + "'";
  if (v.degree.empty())
    s_.fail_at(v.at, what + " holds no scalar triangles (ST, ST2, ST3)" +
                         (v.skipped ? " (" + str(v.skipped) + " points and lines skipped)" : ""));
  // The time step.
  const int64_t nsteps = v.steps;
  auto step_list = [&]() {
    std::string times;
    for (int64_t k = 0; k < std::min<int64_t>(nsteps, 12); ++k)
      times += (k ? ", " : "") + (static_cast<std::size_t>(k) < v.times.size()
                                      ? str(v.times[static_cast<std::size_t>(k)])
                                      : std::string("none"));
    return str(uint64_t(nsteps)) + " time step" + (nsteps == 1 ? "" : "s") + " (times " + times +
           (nsteps > 12 ? ", ..." : "") + ")";
  };
  int64_t step = 0;
  if (field_.time) {
    const double t = *field_.time;
    step = -1;
    for (std::size_t k = 0; k < v.times.size() && step < 0; ++k)
      if (std::abs(v.times[k] - t) <= 1e-9 * std::max(std::abs(v.times[k]), std::abs(t)))
        step = static_cast<int64_t>(k);
    if (step < 0)
      throw InputError(s_.path() + ": --time " + str(t) + ": " + what +
                       " has no time step at that time (" + step_list() + ")");
  } else {
    step = field_.step < 0 ? nsteps + field_.step : field_.step;
    if (step < 0 || step >= nsteps)
      throw InputError(s_.path() + ": --step " + std::to_string(field_.step) + ": " + what +
                       " has " + step_list() + ": steps 0 to " + std::to_string(nsteps - 1) +
                       ", or -" + std::to_string(nsteps) + " to -1 from the end");
  }

  // Every element's own nodes, then merged by position.
  const std::size_t ncells = v.degree.size();
  std::vector<Vec3> points;
  std::vector<double> values;
  std::vector<std::size_t> element_of; // the element (0-based) each point comes from
  points.reserve(v.coords.size() / 3);
  for (std::size_t c = 0; c < ncells; ++c) {
    const auto n = static_cast<std::size_t>(lattice_size(v.degree[c]));
    for (std::size_t i = 0; i < n; ++i) {
      const double *x = v.coords.data() + v.coord_begin[c] + 3 * i;
      points.push_back({x[0], x[1], x[2]});
      values.push_back(v.values[v.value_begin[c] + static_cast<std::size_t>(step) * n + i]);
      element_of.push_back(c);
    }
  }
  std::vector<int64_t> all(points.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<int64_t>(i);
  const double diagonal = bounding_box_diagonal(points);
  const std::vector<int64_t> group =
      diagonal > 0 ? coincident_points(points, all, 1e-9 * diagonal) : std::vector<int64_t>(all);
  // Continuity: the lowest and highest value of each group.
  std::vector<std::size_t> lo(points.size()), hi(points.size());
  std::vector<int64_t> index(points.size(), -1);
  MeshInput m;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto g = static_cast<std::size_t>(group[i]);
    if (index[g] < 0) {
      index[g] = static_cast<int64_t>(m.points.size());
      m.points.push_back(points[g]);
      m.values.push_back(values[g]);
      lo[g] = hi[g] = g;
    }
    if (values[i] < values[lo[g]])
      lo[g] = i;
    if (values[i] > values[hi[g]])
      hi[g] = i;
  }
  double vmin = std::numeric_limits<double>::infinity(), vmax = -vmin, jump = -1;
  std::size_t worst = 0;
  for (std::size_t g = 0; g < points.size(); ++g) {
    if (index[g] < 0)
      continue;
    vmin = std::min(vmin, values[lo[g]]);
    vmax = std::max(vmax, values[hi[g]]);
    if (values[hi[g]] - values[lo[g]] > jump) {
      jump = values[hi[g]] - values[lo[g]];
      worst = g;
    }
  }
  const double range = vmax - vmin;
  const double tolerance = 1e-9 * range + 8 * std::numeric_limits<double>::epsilon() *
                                              std::max(std::abs(vmin), std::abs(vmax));
  if (jump > tolerance) {
    const Vec3 &p = points[worst];
    s_.fail_at(v.element_at[element_of[hi[worst]]],
               what + ": the point (" + str(p[0]) + ", " + str(p[1]) + ", " + str(p[2]) +
                   ") has values " + str(values[lo[worst]]) + " (element " +
                   str(uint64_t{element_of[lo[worst]] + 1}) + ") and " + str(values[hi[worst]]) +
                   " (element " + str(uint64_t{element_of[hi[worst]] + 1}) +
                   "): the field is discontinuous there (largest jump " + str(jump) +
                   " of a range " + str(range) + "); hoct needs a continuous field");
  }
  std::vector<int64_t> canonical;
  for (std::size_t c = 0, first = 0; c < ncells; ++c) {
    const int degree = v.degree[c];
    const std::vector<int> &perm = node_order_to_lattice(NodeOrdering::Gmsh, degree);
    canonical.assign(perm.size(), 0);
    for (std::size_t i = 0; i < perm.size(); ++i)
      canonical[static_cast<std::size_t>(perm[i])] =
          index[static_cast<std::size_t>(group[first + i])];
    m.add_cell(degree, canonical.data());
    first += perm.size();
  }
  m.field_name = v.name;
  if (nsteps > 1)
    m.field_detail =
        "(" +
        step_description(static_cast<std::size_t>(step), static_cast<std::size_t>(nsteps),
                         static_cast<std::size_t>(step) < v.times.size()
                             ? std::optional<double>(v.times[static_cast<std::size_t>(step)])
                             : std::nullopt) +
        ")";
  m.source = s_.path();
  return m;
}

} // namespace

MeshInput read_pos(const std::string &path, const FieldSelection &field, const ReadLimits &limits,
                   FileContents *contents) {
  return PosReader(path, read_whole_file(path), field, limits, contents).read();
}

MeshInput read_pos_buffer(std::string bytes, const std::string &name, const FieldSelection &field,
                          const ReadLimits &limits, FileContents *contents) {
  return PosReader(name, std::move(bytes), field, limits, contents).read();
}

} // namespace hoct
