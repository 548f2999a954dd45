#include "io/field_selection.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

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

std::string format_time(double t) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, t);
  return std::string(buf, r.ptr);
}

std::size_t choose_step(const std::string &where, const std::vector<std::optional<double>> &times,
                        const FieldSelection &field, const std::string &holder) {
  const int64_t n = static_cast<int64_t>(times.size());
  if (field.time) {
    const double t = *field.time;
    double scale = std::abs(t);
    for (const std::optional<double> &s : times)
      scale = std::max(scale, std::abs(s.value_or(0)));
    for (std::size_t i = 0; i < times.size(); ++i)
      if (times[i] && std::abs(*times[i] - t) <= 1e-9 * scale)
        return i;
    std::string listed;
    constexpr std::size_t kShown = 20;
    auto text = [](const std::optional<double> &s) { return s ? format_time(*s) : "none"; };
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (i == kShown && times.size() > kShown + 1) {
        listed +=
            ", ... (" + std::to_string(times.size() - kShown - 1) + " more), " + text(times.back());
        break;
      }
      listed += (i ? ", " : "") + text(times[i]);
    }
    throw InputError(where + ": --time " + format_time(t) + ": no step at that time (the " +
                     std::to_string(n) + " steps' times: " + listed + ")");
  }
  const int64_t i = field.step < 0 ? n + field.step : field.step;
  if (i < 0 || i >= n)
    throw InputError(where + ": --step " + std::to_string(field.step) + ": " + holder + " has " +
                     std::to_string(n) + " step" + (n == 1 ? "" : "s") + " (0 to " +
                     std::to_string(n - 1) + ", or -" + std::to_string(n) + " to -1 from the end)");
  return static_cast<std::size_t>(i);
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
                                       "PedigreeElementId",
                                       "RationalWeights"};
  return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

} // namespace hoct
