// The native module's own checks of what Python passes it, as the command line's (the package
// python/hoct/_arguments.py checks the rest, with Python's types, before calling in): nothing
// with a NUL reaches a file name, no threshold is nan or negative, no point is evaluated
// outside its cell.
#pragma once

#include "util/error.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace hoct::py_checks {

// `x` formatted shortest-exact (nan, inf, -1, 0.25), as the messages quote it.
inline std::string number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

// `s` itself, or an Error: a NUL would end the file name (or array name) early, so that the
// file opened would be its prefix. The command line cannot pass one at all.
inline const std::string &no_nul(const std::string &s, const std::string &what) {
  const std::size_t at = s.find('\0');
  if (at != std::string::npos)
    throw Error(what + " contains a NUL byte at position " + std::to_string(at));
  return s;
}

// An absolute persistence threshold, as parse_threshold (`--simplify`) accepts it.
inline double threshold(double t, const std::string &what) {
  if (!(t >= 0) || !std::isfinite(t))
    throw Error(what + ": " + number(t) +
                " is not a threshold (a finite number >= 0; simplify_by also takes a "
                "percentage like '0.5%')");
  return t;
}

// (cell, u, v) as `hoct eval` accepts it: a cell of the mesh, (u, v) finite and in the
// reference triangle (0,0), (1,0), (0,1), up to 1e-12 on its sides.
inline void eval_point(int64_t cell, double u, double v, int64_t cells) {
  if (cell < 0 || cell >= cells)
    throw Error("value: cell " + std::to_string(cell) + " out of range (the mesh has " +
                std::to_string(cells) + " cells)");
  constexpr double kSlack = 1e-12;
  if (!std::isfinite(u) || !std::isfinite(v) || u < -kSlack || v < -kSlack || u + v > 1 + kSlack)
    throw Error("value: (u, v) = (" + number(u) + ", " + number(v) +
                ") is outside the reference triangle (0,0), (1,0), (0,1): the field is not "
                "defined there");
}

} // namespace hoct::py_checks
