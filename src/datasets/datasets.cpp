#include "datasets/datasets.hpp"

#include "datasets/dataset_options.hpp"
#include "util/error.hpp"

#include <cmath>
#include <utility>

namespace hoct {
namespace {

struct Entry {
  std::string name, description;
  MeshInput (*generate)(const DatasetOptions &);
};

const std::vector<Entry> &registry() {
  static const std::vector<Entry> entries = {
      {"conductor",
       "quadratic temperature on a planar Pi-shaped plate: a constant plateau, exact ridge cells "
       "and ordinary cells (~4,300 cells)",
       generate_conductor},
      {"gauss", "sum of Gaussians on a planar disk, quadratic (~722 cells)", generate_gauss},
      {"heater",
       "sum of Gaussians on a closed finned radiator surface, curved cubic cells (~12,400 cells)",
       generate_heater},
      {"plate",
       "smooth field on a square plate with 10 x 10 square holes: a Reeb graph with loops, any "
       "degree and size (20,000 cubic cells by default)",
       generate_plate},
      {"random",
       "smooth random field (16 cosine modes) on the unit square, any degree and size (20,000 "
       "cubic cells by default)",
       generate_random},
      {"sphere", "sum of sines on the unit sphere, curved cubic cells (~1,000 cells)",
       generate_sphere},
      {"two-triangle",
       "two quintic cells sharing an edge, 16 interior critical points (11 in one cell)",
       generate_two_triangle}};
  return entries;
}

} // namespace

const std::vector<std::string> &dataset_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto &e : registry())
      v.push_back(e.name);
    return v;
  }();
  return names;
}

const std::string &dataset_description(const std::string &name) {
  for (const auto &e : registry())
    if (e.name == name)
      return e.description;
  static const std::string none;
  return none;
}

MeshInput generate_dataset(const std::string &name, const DatasetOptions &options) {
  for (const auto &e : registry())
    if (e.name == name) {
      if (options.frequency != 1 && name != "random")
        throw Error(name + ": --frequency applies to the random dataset only");
      if (options.quadrilaterals && name != "random")
        throw Error(name + ": --quads applies to the random dataset only");
      if (options.plateau != 0 && name != "random")
        throw Error(name + ": --plateau applies to the random dataset only");
      if (!std::isfinite(options.scale) || options.scale == 0 || !std::isfinite(options.offset))
        throw Error(name + ": --scale must be finite and not zero, --offset finite");
      MeshInput mesh = e.generate(options);
      if (options.scale != 1 || options.offset != 0)
        for (double &v : mesh.values)
          v = options.scale * v + options.offset;
      return mesh;
    }
  std::string known;
  for (const auto &e : registry())
    known += (known.empty() ? "" : ", ") + e.name;
  throw Error("unknown dataset '" + name + "' (known: " + known + ")");
}

} // namespace hoct
