// Wall-clock timing of phases (steady clock, seconds as double).
#pragma once

#include <chrono>

namespace hoct {

inline double seconds_between(std::chrono::steady_clock::time_point a,
                              std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

class Stopwatch {
public:
  using clock = std::chrono::steady_clock;
  // Seconds since the start (construction or the last lap).
  double seconds() const { return seconds_between(start_, clock::now()); }
  // Seconds since the start, and restarts.
  double lap() {
    const auto now = clock::now();
    const double s = seconds_between(start_, now);
    start_ = now;
    return s;
  }

private:
  clock::time_point start_ = clock::now();
};

} // namespace hoct
