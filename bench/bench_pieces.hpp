// The distributed tree's phases measured piece by piece in one process (bench --sections
// pieces): what each MPI rank would spend on its piece, what it would send, and what the
// reduction costs, for the scaling model in docs/PERFORMANCE.md.
#pragma once

#include <vector>

namespace hoct::bench {

// One random cubic mesh per size in `sizes`, cut into 2, 8, 32 and 128 pieces; prints a Markdown
// table (seconds: medians of `runs` for the whole-mesh rows; the piece rows run once).
void pieces_section(const std::vector<double> &sizes, int runs);

} // namespace hoct::bench
