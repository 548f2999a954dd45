// Deterministic pseudo-random numbers for the generators: splitmix64, with our own mapping to
// doubles, so a seed gives the same dataset with any compiler and standard library.
#pragma once

#include <cstdint>

namespace hoct {

class SeededRandom {
public:
  explicit SeededRandom(uint64_t seed)
      : state_(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
  uint64_t state_;
};

} // namespace hoct
