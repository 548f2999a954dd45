#include "datasets/datasets.hpp"

#include "datasets/dataset_common.hpp"

namespace hoct {

const std::vector<std::string> &dataset_names() {
  static const std::vector<std::string> names = {"conductor", "gauss",  "heater",
                                                 "random",    "sphere", "two-triangle"};
  return names;
}

const std::string &dataset_description(const std::string &name) {
  static const std::vector<std::pair<std::string, std::string>> d = {
      {"conductor", "quadratic temperature on a planar Pi-shaped plate with plateaus (constant "
                    "cells) and ridges (critical segments), ~4,300 cells"},
      {"gauss", "sum of Gaussians on a planar square, quadratic, 722 cells"},
      {"heater", "sum of Gaussians on a curved closed finned surface (genus 0), cubic, ~12,500 "
                 "cells"},
      {"random", "smooth random field (sum of cosines) on a planar square, any degree and size"},
      {"sphere", "sum of sines on the unit sphere, curved cubic cells, ~1,000 cells"},
      {"two-triangle", "two quintic cells sharing an edge, 16 interior critical points (11 in "
                       "one cell)"}};
  for (const auto &[n, text] : d)
    if (n == name)
      return text;
  static const std::string none;
  return none;
}

MeshInput generate_dataset(const std::string &name, const DatasetOptions &o) {
  if (name == "gauss")
    return generate_gauss(o);
  if (name == "sphere")
    return generate_sphere(o);
  if (name == "two-triangle")
    return generate_two_triangle(o);
  if (name == "heater")
    return generate_heater(o);
  if (name == "conductor")
    return generate_conductor(o);
  if (name == "random")
    return generate_random(o);
  std::string known;
  for (const auto &n : dataset_names())
    known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown dataset '" + name + "' (known: " + known + ")");
}

} // namespace hoct
