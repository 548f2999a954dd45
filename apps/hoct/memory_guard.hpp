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

} // namespace hoct::cli
