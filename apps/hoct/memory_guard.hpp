// The --max-memory option of the commands that read a mesh: a memory budget the readers check
// against an estimate from the file's header counts before allocating (io/read_limits.hpp).
#pragma once

#include "io/read_limits.hpp"

#include <CLI/CLI.hpp>

namespace hoct::cli {

// Adds --max-memory to every subcommand of `app` that reads a mesh (all but generate, compare).
void add_max_memory_option(CLI::App &app);

// The limits from --max-memory (or the default) for the command being run.
ReadLimits read_limits();

// Refuses --refine K on `cells` cells (of `file`; `whose`: whose cells they are, for the
// message) when its sub-triangles need more than the budget (pl/refinement.hpp:
// refinement_memory_bytes): before the refinement allocates them.
void check_refinement_memory(const std::string &file, int64_t cells, int k,
                             const std::string &whose = "");

} // namespace hoct::cli
