// Synthetic datasets modelled on the thesis' chapter 5 (conductor, gauss, heater, sphere,
// two-triangle) plus a smooth random field of any size and degree. Deterministic for a seed.
#pragma once

#include "mesh/mesh_input.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

struct DatasetOptions {
  int degree = 0;      // 0 = the dataset's own default
  long long cells = 0; // target number of cells; 0 = the dataset's own default
  uint64_t seed = 1;
  // `random` only: its wave numbers times this (features per unit area grow with its square);
  // with the square root of the cell count's growth, every size has the same features per cell.
  double frequency = 1;
  // `random` only: the node values below their P-th percentile raised to it (0 <= P < 100): a
  // plateau over about P% of the square, of constant cells where all of a cell's nodes are
  // raised, as in clamped FEM fields (a concentration cut at zero, a saturated phase field).
  double plateau = 0;
  // Every dataset: its values v become scale * v + offset (rounded once, as a solver writing
  // kelvin or pascal would): the same field shifted and scaled, for invariance tests.
  double scale = 1;
  double offset = 0;
  // `random` only: Lagrange quadrilaterals of order `degree` instead of triangles, on the same
  // grid (its rectangles uncut): about `cells` quadrilaterals, the nodes of twice as many
  // triangles of that degree.
  bool quadrilaterals = false;
};

// Names accepted by generate_dataset, in a stable order.
const std::vector<std::string> &dataset_names();

// One line describing a dataset (empty for an unknown name).
const std::string &dataset_description(const std::string &name);

// Builds the dataset. Throws hoct::Error for an unknown name or options out of range.
MeshInput generate_dataset(const std::string &name, const DatasetOptions &options);

} // namespace hoct
