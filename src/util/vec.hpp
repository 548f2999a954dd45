// Points and vectors: in the reference triangle (Vec2, parameters u, v) and in space (Vec3).
#pragma once

#include <array>

namespace hoct {

using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

} // namespace hoct
