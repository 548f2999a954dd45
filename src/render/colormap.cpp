#include "render/colormap.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {

std::array<double, 3> viridis(double t) {
  // Viridis at t = 0, 0.1, ..., 1.
  static constexpr unsigned kAnchors[11] = {0x440154, 0x482475, 0x414487, 0x355F8D,
                                            0x2A788E, 0x21918C, 0x22A884, 0x44BF70,
                                            0x7AD151, 0xBDDF26, 0xFDE725};
  if (!(t >= 0))
    t = 0;
  t = std::min(t, 1.0);
  const double x = t * 10;
  const int i = std::min(9, static_cast<int>(std::floor(x)));
  const double f = x - i;
  std::array<double, 3> c;
  for (int k = 0; k < 3; ++k) {
    const double a = ((kAnchors[i] >> (16 - 8 * k)) & 255) / 255.0;
    const double b = ((kAnchors[i + 1] >> (16 - 8 * k)) & 255) / 255.0;
    c[k] = a + f * (b - a);
  }
  return c;
}

} // namespace hoct
