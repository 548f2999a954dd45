// The options that choose the field a command reads: --scalar, --component, --step, --time.
#pragma once

#include "io/field_selection.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace hoct::cli {

struct FieldOptions {
  std::string scalar, component;
  int64_t step = -1;
  double time = 0;
  CLI::Option *time_option = nullptr;
  // Throws hoct::Error for a bad --component.
  FieldSelection selection() const;
};

void add_field_options(CLI::App *sub, FieldOptions &field);

} // namespace hoct::cli
