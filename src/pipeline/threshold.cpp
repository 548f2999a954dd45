#include "pipeline/threshold.hpp"

#include "util/error.hpp"

#include <cmath>
#include <exception>

namespace hoct {

Threshold parse_threshold(const std::string &text, const std::string &what) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  double v = 0;
  std::size_t used = 0;
  try {
    v = std::stod(number, &used);
  } catch (const std::exception &) {
    used = 0;
  }
  if (used != number.size() || number.empty() || !(v >= 0) || !std::isfinite(v))
    throw Error(what + ": '" + text + "' is not a threshold (a number, or a percentage like 0.5%)");
  return {v, percent};
}

} // namespace hoct
