#include "io/read_limits.hpp"

#include "util/error.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace hoct {

// Bytes per item, fitted to the peak RSS of `hoct tree` on generated meshes (gauss of degrees 1
// and 3, heater of degree 2) and rounded up, so that the estimate stays above the peak: per node
// (position, value, Bernstein and geometry coefficients, tree nodes), per cell (topology,
// per-cell tree work), per connectivity entry.
namespace {
constexpr uint64_t kBytesPerPoint = 160;
constexpr uint64_t kBytesPerCellNode = 16;
constexpr uint64_t kBytesPerCell = 640;
constexpr uint64_t kBaseBytes = 32ull << 20; // the process itself
} // namespace

uint64_t estimate_memory_bytes(uint64_t points, uint64_t cells, uint64_t cell_nodes) {
  // Saturating: counts come from untrusted headers.
  const long double e = static_cast<long double>(points) * kBytesPerPoint +
                        static_cast<long double>(cells) * kBytesPerCell +
                        static_cast<long double>(cell_nodes) * kBytesPerCellNode + kBaseBytes;
  return e >= 1.8e19L ? UINT64_MAX : static_cast<uint64_t>(e);
}

std::string format_bytes(uint64_t bytes) {
  char buf[64];
  const double b = static_cast<double>(bytes);
  if (b >= 1024.0 * 1024 * 1024 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.3g PiB", b / (1024.0 * 1024 * 1024 * 1024 * 1024));
  else if (b >= 1024.0 * 1024 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.3g TiB", b / (1024.0 * 1024 * 1024 * 1024));
  else if (b >= 1024.0 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.3g GiB", b / (1024.0 * 1024 * 1024));
  else
    std::snprintf(buf, sizeof buf, "%.3g MiB", b / (1024.0 * 1024));
  return buf;
}

void check_memory(const ReadLimits &limits, uint64_t points, uint64_t cells, uint64_t cell_nodes,
                  const std::string &where) {
  if (limits.max_memory_bytes == 0)
    return;
  const bool prior = limits.prior_points || limits.prior_cells || limits.prior_cell_nodes;
  // Saturating: the sums come from untrusted headers too.
  auto add = [](uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; };
  points = add(points, limits.prior_points);
  cells = add(cells, limits.prior_cells);
  cell_nodes = add(cell_nodes, limits.prior_cell_nodes);
  const uint64_t need = estimate_memory_bytes(points, cells, cell_nodes);
  if (need > limits.max_memory_bytes)
    throw InputError(
        where + ": " + std::to_string(points) + " points and " + std::to_string(cells) + " cells" +
        (prior ? std::string(" (with the pieces read before)") : std::string()) + " need ~" +
        format_bytes(need) + ", limit " + format_bytes(limits.max_memory_bytes) +
        " (raise it with --max-memory, e.g. --max-memory 90%)");
}

uint64_t parse_memory_size(const std::string &text, uint64_t physical_bytes) {
  const auto bad = [&]() -> uint64_t {
    throw Error("bad memory size '" + text + "' (expected e.g. 512M, 8G, 2.5GiB or 50%)");
  };
  double v = 0;
  const char *b = text.data(), *e = text.data() + text.size();
  const auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || !std::isfinite(v) || v <= 0)
    return bad();
  std::string unit(r.ptr, e);
  for (auto &c : unit)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  double scale = 1;
  if (unit == "%") {
    if (physical_bytes == 0)
      throw Error("memory size '" + text + "': the physical memory size is unknown");
    if (v > 100)
      return bad();
    scale = static_cast<double>(physical_bytes) / 100;
  } else if (unit.empty() || unit == "B")
    scale = 1;
  else if (unit == "K" || unit == "KB" || unit == "KIB")
    scale = 1024.0;
  else if (unit == "M" || unit == "MB" || unit == "MIB")
    scale = 1024.0 * 1024;
  else if (unit == "G" || unit == "GB" || unit == "GIB")
    scale = 1024.0 * 1024 * 1024;
  else if (unit == "T" || unit == "TB" || unit == "TIB")
    scale = 1024.0 * 1024 * 1024 * 1024;
  else
    return bad();
  const double bytes = v * scale;
  if (bytes >= 1.8e19)
    return bad();
  return std::max<uint64_t>(1, static_cast<uint64_t>(bytes));
}

uint64_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || size <= 0)
    return 0;
  return static_cast<uint64_t>(pages) * static_cast<uint64_t>(size);
}

ReadLimits read_limits_for(const std::string &max_memory) {
  const uint64_t physical = physical_memory_bytes();
  if (!max_memory.empty())
    return {.max_memory_bytes = parse_memory_size(max_memory, physical)};
  return {.max_memory_bytes = physical / 100 * kDefaultMemoryPercent};
}

} // namespace hoct
