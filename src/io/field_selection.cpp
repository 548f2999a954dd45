#include "io/field_selection.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace hoct {

std::string FieldSelection::describe(const std::string &chosen_name) const {
  if (component == kMagnitude)
    return "|" + chosen_name + "|";
  if (component >= 0)
    return chosen_name + "[" + std::to_string(component) + "]";
  return chosen_name;
}

std::string step_description(std::size_t step, std::size_t steps, std::optional<double> time) {
  std::string s = "step " + std::to_string(step) + " of " + std::to_string(steps);
  if (time) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, *time);
    s.append(", time ").append(buf, r.ptr);
  }
  return s;
}

int parse_component(const std::string &text) {
  std::string t = text;
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
  if (t == "magnitude" || t == "mag" || t == "norm")
    return FieldSelection::kMagnitude;
  if (t == "x")
    return 0;
  if (t == "y")
    return 1;
  if (t == "z")
    return 2;
  int v = -1;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || v < 0 || v > 63)
    throw Error("--component '" + text +
                "': expected a component index (0, 1, ...), x, y, z or magnitude");
  return v;
}

bool is_bookkeeping_array(const std::string &name) {
  if (name.rfind("vtk", 0) == 0) // vtkOriginalPointIds, vtkGhostType, vtkValidPointMask, ...
    return true;
  static const char *const kNames[] = {"GlobalIds",
                                       "GlobalPointIds",
                                       "GlobalCellIds",
                                       "GlobalNodeIds",
                                       "GlobalElementIds",
                                       "PedigreeIds",
                                       "ids",
                                       "Ids",
                                       "original_ids",
                                       "mask",
                                       "ghost",
                                       "GhostLevels",
                                       "ObjectId",
                                       "BlockId",
                                       "GlobalNodeId",
                                       "PedigreeNodeId",
                                       "GlobalElementId",
                                       "PedigreeElementId"};
  return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

} // namespace hoct
