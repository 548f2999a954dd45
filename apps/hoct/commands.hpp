// The hoct command-line tool: each subcommand lives in its own cmd_*.cpp and registers itself
// on the top-level CLI11 app. Commands are thin: they parse options, call the library, print.
#pragma once

#include <CLI/CLI.hpp>

namespace hoct::cli {

void register_info(CLI::App &app);
void register_generate(CLI::App &app);
void register_eval(CLI::App &app);
void register_tree(CLI::App &app);
void register_compare(CLI::App &app);
void register_render(CLI::App &app);
void register_study(CLI::App &app);
void register_convert(CLI::App &app);
void register_check(CLI::App &app);

} // namespace hoct::cli
