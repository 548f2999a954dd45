#include "poly/lattice.hpp"

namespace hoct {

std::array<int, 2> lattice_point(int d, int index) {
  int b = 0;
  while (index >= d + 1 - b) {
    index -= d + 1 - b;
    ++b;
  }
  return {index, b};
}

} // namespace hoct
