// Resource limits and threads for the readers: a memory budget checked against an estimate computed
// from the counts in a file's headers before the reader allocates for them. The estimate covers the
// whole pipeline (the MeshInput, the checked Mesh and the exact contour tree of it), so an input
// that cannot be processed fails early with "needs ~X GiB, limit Y GiB" instead of being killed
// later.
#pragma once

#include <cstdint>
#include <string>

namespace hoct {

struct ReadLimits {
  // Memory budget in bytes; 0 = no limit.
  uint64_t max_memory_bytes = 0;
  // VTU files larger than this whose payload is raw appended data are not read whole: the XML
  // around the payload is, and each array is read from the file straight into its destination.
  uint64_t stream_appended_above = uint64_t{64} << 20;
  // Threads that read such arrays from the file, each a part (0 = all hardware threads): copying
  // from the page cache and mapping the destination's fresh pages scale with them.
  int threads = 1;
  // What a collection reader (.pvtu, .pvd) has read before this file, its earlier pieces:
  // counted in the budget with the file's own counts.
  uint64_t prior_points = 0, prior_cells = 0, prior_cell_nodes = 0;
};

// Estimated peak bytes to read, build and compute the exact tree of a mesh with `points` nodes,
// `cells` triangles and `cell_nodes` entries in the connectivity (sum of the nodes per cell).
uint64_t estimate_memory_bytes(uint64_t points, uint64_t cells, uint64_t cell_nodes);

// Throws InputError "<where>: <what> needs ~X GiB, limit Y GiB (...)" if the estimate exceeds
// the limit. The limits' prior counts are added to the ones given.
void check_memory(const ReadLimits &limits, uint64_t points, uint64_t cells, uint64_t cell_nodes,
                  const std::string &where);

// "1.5 GiB", "300 MiB", ...
std::string format_bytes(uint64_t bytes);

// Parses a size: a number with an optional unit K, M, G, T (powers of 1024; "GiB"/"GB" accepted)
// or "%" of the physical memory ("50%"). Throws Error on bad input.
uint64_t parse_memory_size(const std::string &text, uint64_t physical_bytes);

// Physical memory of the machine in bytes (0 if unknown).
uint64_t physical_memory_bytes();

// Default budget of the command line and the Python module: this share of the physical memory.
constexpr int kDefaultMemoryPercent = 80;

// The limits for a budget given as text (parse_memory_size; empty = the default share).
ReadLimits read_limits_for(const std::string &max_memory);

} // namespace hoct
