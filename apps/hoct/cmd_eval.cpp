// `hoct eval FILE --points PTS`: the field and the geometry map at parametric points of cells.
#include "commands.hpp"
#include "load_mesh.hpp"
#include "util/error.hpp"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace hoct::cli {
namespace {

struct EvalOptions {
  std::string file, scalar, points = "-";
};

void run_eval(const EvalOptions &o) {
  const LoadedMesh lm = load_mesh(o.file, o.scalar, /*strict=*/true);
  const Mesh &m = lm.mesh;
  std::ifstream file;
  std::istream *in = &std::cin;
  if (o.points != "-") {
    file.open(o.points);
    if (!file)
      throw Error(o.points + ": cannot open");
    in = &file;
  }
  const std::string where = o.points == "-" ? "<stdin>" : o.points;
  std::string line;
  long long lineno = 0;
  while (std::getline(*in, line)) {
    ++lineno;
    std::istringstream ls(line);
    long long c;
    double u, v;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#')
      continue;
    if (!(ls >> c >> u >> v))
      throw Error(where + ":" + std::to_string(lineno) + ": expected 'cell u v', got '" + line +
                  "'");
    if (c < 0 || c >= m.topology.num_cells())
      throw Error(where + ":" + std::to_string(lineno) + ": cell " + std::to_string(c) +
                  " out of range (the mesh has " + std::to_string(m.topology.num_cells()) +
                  " cells)");
    const Vec3 p = m.geometry.position(c, u, v);
    std::printf("%lld %.17g %.17g %.17g %.17g %.17g %.17g\n", c, u, v, p[0], p[1], p[2],
                m.field.value(c, u, v));
  }
}

} // namespace

void register_eval(CLI::App &app) {
  auto o = std::make_shared<EvalOptions>();
  auto *sub = app.add_subcommand(
      "eval", "Evaluate the field and the geometry at parametric points: reads lines 'cell u v' "
              "(reference triangle (0,0),(1,0),(0,1)), prints 'cell u v x y z value'");
  sub->add_option("file", o->file, "Input file (.vtu, .msh)")->required();
  sub->add_option("--scalar", o->scalar, "Point-data array / node-data view (default: the first)");
  sub->add_option("--points", o->points, "File of 'cell u v' lines, or - for stdin");
  sub->callback([o] { run_eval(*o); });
}

} // namespace hoct::cli
