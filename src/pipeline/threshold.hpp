// A persistence threshold as users write it: absolute ("0.01") or a percentage of the tree's
// value range ("0.5%").
#pragma once

#include <string>

namespace hoct {

struct Threshold {
  double value = 0;
  bool percent = false; // value is in % of the value range

  // The absolute threshold for a tree whose values span `range`.
  double absolute(double range) const { return percent ? value / 100 * range : value; }
};

// Parses "0.01" or "0.5%"; throws hoct::Error naming `what` (e.g. "--simplify") for anything
// else (empty, negative, not finite, trailing characters).
Threshold parse_threshold(const std::string &text, const std::string &what = "simplify");

} // namespace hoct
