// Which field a reader takes from a file: the array (VTK point data) or view (Gmsh node data) by
// name, one component of a vector or its magnitude, and the time step of files that hold
// several. The readers apply it; the CLI (--scalar, --component, --step, --time) and the Python
// module fill it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hoct {

struct FieldSelection {
  // The array or view; empty = the reader's default: the first one-component floating-point
  // array that is not an id, ghost or mask array (vtkOriginalPointIds, vtkGhostType,
  // GlobalIds, ...), else the first one-component array of those.
  std::string name;
  // kScalar: the array must have one component. 0, 1, ...: that component of a vector array.
  // kMagnitude: the Euclidean norm of its components.
  static constexpr int kScalar = -1, kMagnitude = -2;
  int component = kScalar;
  // Files with several time steps (collections, Gmsh views written per step): the step's index
  // from 0, negative from the end (-1, the default: the last). `time`, when set, chooses the
  // step at that time instead.
  int64_t step = -1;
  std::optional<double> time;

  FieldSelection() = default;
  // A name alone, as the readers took before (implicit: read_mesh(path, "T") keeps working).
  FieldSelection(std::string field_name) : name(std::move(field_name)) {}
  FieldSelection(const char *field_name) : name(field_name) {}

  bool default_step() const { return step == -1 && !time; }
  // The field as the summary names it: "T", "U[1]", "|U|".
  std::string describe(const std::string &chosen_name) const;
};

// "step 2 of 3, time 0.2" (the time only if there is one; the shortest text that reads back as
// it): which time step a reader read, for MeshInput::field_detail.
std::string step_description(std::size_t step, std::size_t steps, std::optional<double> time);

// A time as the summaries write it: the shortest text that reads back to it ("0.1").
std::string format_time(double t);

// The step `field` chooses among steps at `times` (a file's or a collection's, in order): by
// --time (equal within 1e-9 of the largest time's magnitude; every step must have a time) or by
// --step (from 0, negative from the end). Throws InputError "<where>: --time T: no step at that
// time (the N steps' times: ...)" or "<where>: --step S: <holder> has N steps (0 to N-1, ...)".
std::size_t choose_step(const std::string &where, const std::vector<std::optional<double>> &times,
                        const FieldSelection &field, const std::string &holder);

// Parses --component: a non-negative integer, x / y / z (0, 1, 2) or "magnitude". Throws
// hoct::Error for anything else.
int parse_component(const std::string &text);

// True for the arrays a default choice skips: ids, ghost levels and masks that writers put
// first (DOLFINx's vtkOriginalPointIds, VTK's vtkGhostType, GlobalIds, PedigreeIds, ...).
bool is_bookkeeping_array(const std::string &name);

} // namespace hoct
