// A perceptually uniform colour map (viridis, from its published anchor colours, linearly
// interpolated) for field values.
#pragma once

#include <array>

namespace hoct {

// RGB in [0, 1] for t in [0, 1] (clamped).
std::array<double, 3> viridis(double t);

} // namespace hoct
