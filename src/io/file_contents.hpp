// What a mesh file offers to choose from, as a reader saw it: its fields (VTK arrays, Gmsh
// views) with their kind, components and time steps. `hoct info` lists them; the core never
// sees it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hoct {

struct FileFieldStep {
  int64_t tag = 0;            // the file's own step number (Gmsh: the time-step integer tag)
  std::optional<double> time; // its time, if the file gives one
};

struct FileField {
  std::string name;
  std::string kind; // "node data", "element-node data", "element data"
  int64_t components = 1;
  std::vector<FileFieldStep> steps; // in file order: --step N is steps[N]
};

struct FileContents {
  std::vector<FileField> fields;
};

} // namespace hoct
