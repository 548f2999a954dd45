#include "field_options.hpp"

namespace hoct::cli {

FieldSelection FieldOptions::selection() const {
  FieldSelection f(scalar);
  if (!component.empty())
    f.component = parse_component(component);
  f.step = step;
  if (time_option && time_option->count() > 0)
    f.time = time;
  return f;
}

void add_field_options(CLI::App *sub, FieldOptions &field) {
  sub->add_option("--scalar", field.scalar,
                  "Point-data array / node-data view (default: the active scalars, else the "
                  "first floating-point one that is no id, ghost or mask array)");
  sub->add_option("--component", field.component,
                  "Of a vector array: component N (0, 1, ... or x, y, z) or 'magnitude'");
  sub->add_option("--step", field.step,
                  "Time step of files that hold several: index from 0, negative from the end "
                  "(default -1: the last)");
  field.time_option =
      sub->add_option("--time", field.time, "Time step at this time (instead of --step)");
}

} // namespace hoct::cli
