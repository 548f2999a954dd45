// Deterministic pseudo-random numbers for the dataset generators: splitmix64 with our own mapping
// to doubles, so a seed gives bit-identical datasets with any compiler and standard library
// (std::uniform_real_distribution and friends are not specified exactly).
#pragma once

#include <cstdint>

namespace hoct {

class SeededRandom {
public:
  // `stream` separates independent sequences drawn from the same seed (e.g. the field and the
  // mesh jitter), so changing how many numbers one of them draws does not shift the other.
  explicit SeededRandom(uint64_t seed, uint64_t stream = 0)
      : state_(mix(seed ^ mix(stream + 0x632BE59BD9B4E019ull))) {}

  uint64_t next() { return mix(state_ += 0x9E3779B97F4A7C15ull); }

  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // -1 or +1 with equal probability.
  double sign() { return (next() >> 63) ? 1.0 : -1.0; }

private:
  static uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  uint64_t state_;
};

} // namespace hoct
