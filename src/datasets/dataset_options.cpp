#include "datasets/dataset_options.hpp"

#include "poly/lattice.hpp"
#include "util/error.hpp"

#include <cstdio>

namespace hoct {

int dataset_degree(const DatasetOptions &o, int default_degree, const std::string &name) {
  const int d = o.degree != 0 ? o.degree : default_degree;
  if (d < 1 || d > 10)
    throw Error(name + ": --degree must be between 1 and 10, got " + std::to_string(d));
  return d;
}

long long dataset_cells(const DatasetOptions &o, long long default_cells, long long min_cells,
                        long long max_cells, int degree, const std::string &name) {
  const long long n = o.cells != 0 ? o.cells : default_cells;
  if (n < min_cells || n > max_cells)
    throw Error(name + ": --cells must be between " + std::to_string(min_cells) + " and " +
                std::to_string(max_cells) + ", got " + std::to_string(n));
  // Cell node ids alone take 8 bytes per lattice node; 4e8 of them (3.2 GB, and as much again
  // for points and values) is the most we build.
  const double nodes = static_cast<double>(n) * lattice_size(degree);
  if (nodes > 4e8)
    throw Error(name + ": " + std::to_string(n) + " cells of degree " + std::to_string(degree) +
                " are too large (more than 4e8 cell nodes); lower --cells or --degree");
  return n;
}

std::string dataset_source(const std::string &name, const DatasetOptions &o, int degree) {
  std::string s =
      "generated:" + name + " seed=" + std::to_string(o.seed) + " degree=" + std::to_string(degree);
  if (o.frequency != 1) {
    char f[32];
    std::snprintf(f, sizeof f, " frequency=%g", o.frequency);
    s += f;
  }
  if (o.plateau != 0) {
    char f[32];
    std::snprintf(f, sizeof f, " plateau=%g", o.plateau);
    s += f;
  }
  if (o.quadrilaterals)
    s += " quads";
  if (o.scale != 1 || o.offset != 0) {
    char f[64];
    std::snprintf(f, sizeof f, " scale=%.17g offset=%.17g", o.scale, o.offset);
    s += f;
  }
  return s;
}

} // namespace hoct
