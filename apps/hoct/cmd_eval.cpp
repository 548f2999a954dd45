// `hoct eval FILE --points PTS`: the field and the geometry map at parametric points of cells.
#include "commands.hpp"
#include "field_options.hpp"
#include "load_mesh.hpp"
#include "util/error.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace hoct::cli {
namespace {

struct EvalOptions {
  std::string file, points = "-";
  FieldOptions field;
};

// Lines longer than this are refused (a point line is a few dozen bytes; /dev/zero has none).
constexpr std::size_t kMaxLine = 4096;

// The line for an error message: at most 60 bytes of it, printable characters only.
std::string quote_prefix(const std::string &line) {
  std::string q;
  for (char ch : line.substr(0, 60))
    q.push_back(static_cast<unsigned char>(ch) >= 32 && ch != 127 ? ch : '?');
  return "'" + q + (line.size() > 60 ? "...'" : "'");
}

// The next line of `in` into `line` (without the newline); false at the end. Throws past
// kMaxLine bytes without reading further.
bool read_line(std::istream &in, std::string &line, const std::string &where, long long lineno) {
  // istream::getline stores at most size - 1 bytes and sets failbit when the line goes on.
  thread_local std::vector<char> buffer(kMaxLine + 1);
  in.getline(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  const std::streamsize got = in.gcount(); // with the newline, if one was extracted
  if (in.fail() && !in.eof() && got == static_cast<std::streamsize>(kMaxLine)) {
    line.assign(buffer.data(), kMaxLine);
    throw Error(where + ":" + std::to_string(lineno) + ": line longer than " +
                std::to_string(kMaxLine) + " bytes (it starts " + quote_prefix(line) +
                "): not a file of 'cell u v' lines");
  }
  if (got == 0)
    return false; // the end
  const std::size_t length = static_cast<std::size_t>(got) - (in.eof() ? 0 : 1);
  line.assign(buffer.data(), length);
  if (in.eof())
    in.clear(std::ios::eofbit); // a last line without a newline: the next call ends
  return true;
}

// The fields of `line` separated by blanks, parsed in place: true if there are exactly three,
// an integer cell id and two finite numbers.
bool parse_point(const std::string &line, long long &c, double &u, double &v) {
  const char *p = line.data(), *end = p + line.size();
  auto blank = [](char ch) { return ch == ' ' || ch == '\t' || ch == '\r'; };
  auto field = [&](auto &x) {
    while (p < end && blank(*p))
      ++p;
    const char *stop = p;
    while (stop < end && !blank(*stop))
      ++stop;
    if (stop == p)
      return false;
    const auto r = std::from_chars(p, stop, x);
    const bool whole = r.ec == std::errc() && r.ptr == stop;
    p = stop;
    return whole;
  };
  if (!field(c) || !field(u) || !field(v) || !std::isfinite(u) || !std::isfinite(v))
    return false;
  while (p < end && blank(*p))
    ++p;
  return p == end;
}

void run_eval(const EvalOptions &o) {
  const LoadedMesh lm = load_mesh(o.file, o.field.selection(), /*strict=*/true);
  const Mesh &m = lm.mesh;
  std::ifstream file;
  std::istream *in = &std::cin;
  if (o.points != "-") {
    std::error_code ec;
    if (std::filesystem::is_directory(o.points, ec))
      throw Error(o.points + ": is a directory, not a file of 'cell u v' lines");
    file.open(o.points, std::ios::binary);
    if (!file)
      throw Error(o.points + ": cannot open");
    in = &file;
  }
  const std::string where = o.points == "-" ? "<stdin>" : o.points;
  std::string line;
  long long lineno = 0;
  constexpr double kSlack = 1e-12; // on the reference triangle's sides
  while (read_line(*in, line, where, lineno + 1)) {
    ++lineno;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#')
      continue;
    const std::string at = where + ":" + std::to_string(lineno) + ": ";
    long long c;
    double u, v;
    if (!parse_point(line, c, u, v))
      throw Error(at + "expected 'cell u v' (an integer cell id and two numbers), got " +
                  quote_prefix(line));
    const int64_t cells = m.origins.num_input_cells(m.topology.num_cells());
    if (c < 0 || c >= cells)
      throw Error(at + "cell " + std::to_string(c) + " out of range (the mesh has " +
                  std::to_string(cells) + " cells)");
    const bool quad = m.origins.quadrilateral(c);
    if (quad && (u < -kSlack || v < -kSlack || u > 1 + kSlack || v > 1 + kSlack))
      throw Error(at + "(s, t) = (" + std::to_string(u) + ", " + std::to_string(v) +
                  ") is outside the unit square of quadrilateral " + std::to_string(c) +
                  ": the field is not defined there");
    if (!quad && (u < -kSlack || v < -kSlack || u + v > 1 + kSlack))
      throw Error(at + "(u, v) = (" + std::to_string(u) + ", " + std::to_string(v) +
                  ") is outside the reference triangle (0,0), (1,0), (0,1): the field is not "
                  "defined there");
    const CellPlace at_mesh = m.origins.to_mesh(c, {u, v});
    const int64_t t = at_mesh.cell;
    const double a = at_mesh.uv[0], b = at_mesh.uv[1];
    const Vec3 p = m.geometry.position(t, a, b);
    std::printf("%lld %.17g %.17g %.17g %.17g %.17g %.17g\n", c, u, v, p[0], p[1], p[2],
                m.field.value(t, a, b));
  }
  if (in->bad())
    throw Error(where + ": read error");
}

} // namespace

void register_eval(CLI::App &app) {
  auto o = std::make_shared<EvalOptions>();
  auto *sub = app.add_subcommand(
      "eval", "Evaluate the field and the geometry at parametric points: reads lines 'cell u v' "
              "(reference triangle (0,0),(1,0),(0,1); a quadrilateral's unit square (s, t), (0,0) "
              "at its first corner), prints 'cell u v x y z value'");
  sub->add_option("file", o->file, "Input file (.vtu, .pvtu, .pvd, .msh, .pos)")->required();
  add_field_options(sub, o->field);
  sub->add_option("--points", o->points, "File of 'cell u v' lines, or - for stdin");
  sub->callback([o] { run_eval(*o); });
}

} // namespace hoct::cli
