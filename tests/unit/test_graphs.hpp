// Small graphs built by hand in tests: a ContourTree from node values (ascending in the total
// order) and arcs (lower node first), node ids 0..n-1.
#pragma once

#include "tree/contour_tree.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace hoct::testing {

inline ContourTree graph_of(std::vector<double> values, std::vector<std::array<int64_t, 2>> arcs) {
  ContourTree g;
  for (std::size_t i = 0; i < values.size(); ++i)
    g.nodes.push_back(static_cast<int64_t>(i));
  g.values = std::move(values);
  std::sort(arcs.begin(), arcs.end());
  g.arcs = std::move(arcs);
  return g;
}

} // namespace hoct::testing
