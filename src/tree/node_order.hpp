// The one total order on graph nodes, (value, then id), as a sorted list: the values' bit
// patterns (mapped so that unsigned order is numeric order, -0 = +0) partitioned by their
// leading differing bits, then each part sorted by (pattern, id) in cache.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// The nodes in ascending total order: ascending[r] is the node of rank r. Values must not be
// NaN (inputs are checked for it). On `threads` threads from 65,536 values; the same result on
// any.
std::vector<int64_t> ascending_order(std::span<const double> values, int threads = 1);
// The same into `out` (values.size() entries).
void ascending_order(std::span<const double> values, std::span<int64_t> out, int threads = 1);

} // namespace hoct
