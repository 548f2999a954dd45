// Resolving a generator's options (datasets/datasets.hpp) against its defaults and limits, and
// the `source` description of a generated mesh.
#pragma once

#include "datasets/datasets.hpp"

#include <string>

namespace hoct {

// The requested degree, or `default_degree` if none; hoct::Error unless 1 <= degree <= 10.
int dataset_degree(const DatasetOptions &options, int default_degree, const std::string &name);

// The requested target cell count, or `default_cells` if none; hoct::Error outside
// [min_cells, max_cells] or if cells x nodes per cell of `degree` is too large to hold.
long long dataset_cells(const DatasetOptions &options, long long default_cells, long long min_cells,
                        long long max_cells, int degree, const std::string &name);

// "generated:NAME seed=S degree=D".
std::string dataset_source(const std::string &name, const DatasetOptions &options, int degree);

// Generators, one per file.
MeshInput generate_gauss(const DatasetOptions &options);
MeshInput generate_sphere(const DatasetOptions &options);
MeshInput generate_two_triangle(const DatasetOptions &options);
MeshInput generate_heater(const DatasetOptions &options);
MeshInput generate_conductor(const DatasetOptions &options);
MeshInput generate_random(const DatasetOptions &options);
MeshInput generate_plate(const DatasetOptions &options);

} // namespace hoct
