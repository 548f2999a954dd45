// The shape of a tree as text, for tests that know it by hand: "type(down,up)" per node in
// ascending order.
#pragma once

#include "tree/tree_result.hpp"

#include <string>

namespace hoct::testing {

inline std::string tree_shape(const TreeResult &t) {
  std::string s;
  for (const auto &n : t.nodes)
    s += std::string(s.empty() ? "" : " ") + to_string(n.type) + "(" + std::to_string(n.down) +
         "," + std::to_string(n.up) + ")";
  return s;
}

} // namespace hoct::testing
