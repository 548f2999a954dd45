#include "memory_guard.hpp"

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

} // namespace hoct::cli
