// Shared pieces of the dataset generators.
#pragma once

#include "datasets/datasets.hpp"
#include "error.hpp"

#include <cmath>
#include <string>

namespace hoct {

inline int dataset_degree(const DatasetOptions &o, int default_degree, const std::string &name) {
  const int d = o.degree > 0 ? o.degree : default_degree;
  if (d < 1 || d > 10)
    throw Error(name + ": degree must be between 1 and 10, got " + std::to_string(d));
  return d;
}

inline long long dataset_cells(const DatasetOptions &o, long long default_cells,
                               const std::string &name) {
  const long long n = o.cells > 0 ? o.cells : default_cells;
  if (n < 2 || n > 100000000)
    throw Error(name + ": --cells must be between 2 and 1e8, got " + std::to_string(n));
  return n;
}

inline std::string dataset_source(const std::string &name, const DatasetOptions &o, int degree) {
  return "generated:" + name + " degree=" + std::to_string(degree) +
         " seed=" + std::to_string(o.seed);
}

// Generators, one per file.
MeshInput generate_gauss(const DatasetOptions &o);
MeshInput generate_sphere(const DatasetOptions &o);
MeshInput generate_two_triangle(const DatasetOptions &o);
MeshInput generate_heater(const DatasetOptions &o);
MeshInput generate_conductor(const DatasetOptions &o);
MeshInput generate_random(const DatasetOptions &o);

} // namespace hoct
