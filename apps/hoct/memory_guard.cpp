#include "memory_guard.hpp"

#include "pl/refinement.hpp"
#include "util/error.hpp"

#include <string>

namespace hoct::cli {
namespace {

std::string &max_memory_text() {
  static std::string text;
  return text;
}

} // namespace

void add_max_memory_option(CLI::App &app) {
  for (CLI::App *sub : app.get_subcommands({})) {
    const std::string name = sub->get_name();
    if (name == "generate" || name == "compare")
      continue;
    sub->add_option("--max-memory", max_memory_text(),
                    "Memory budget, e.g. 8G, 512M or 50% of the physical memory (default " +
                        std::to_string(kDefaultMemoryPercent) +
                        "%); inputs whose header counts need more are refused before reading");
  }
}

ReadLimits read_limits() { return read_limits_for(max_memory_text()); }

void check_refinement_memory(const std::string &file, int64_t cells, int k,
                             const std::string &whose) {
  const uint64_t budget = read_limits().max_memory_bytes;
  const uint64_t need = refinement_memory_bytes(cells, k);
  if (budget > 0 && need > budget)
    throw Error(file + ": --refine " + std::to_string(k) + ": " + std::to_string(cells) + " cells" +
                whose + " of " + std::to_string(k) + " x " + std::to_string(k) +
                " sub-triangles need ~" + format_bytes(need) + ", limit " + format_bytes(budget) +
                " (lower K, or raise the limit with --max-memory)");
}

} // namespace hoct::cli
