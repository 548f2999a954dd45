// Reader for VTK XML collections (.pvd): the data sets of a time series, one step chosen
// (FieldSelection::step, default the last, or ::time) and read; its parts joined.
#pragma once

#include "io/field_selection.hpp"
#include "io/read_limits.hpp"
#include "mesh/mesh_input.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hoct {

// One time step of a collection: the <DataSet>s of one timestep (several parts, or one).
struct PvdStep {
  std::optional<double> time;      // none when the data sets have no timestep attribute
  std::vector<std::string> listed; // each part's file as the collection names it
  std::vector<std::string> files;  // and as a path (relative to the collection's directory)
};

// The steps of the collection at `path`, sorted by time (the data sets of equal timestep are
// the parts of one step). Throws InputError naming the file for a malformed collection: no
// <DataSet>, a timestep that is no finite number, a timestep on some data sets only, a file
// that is no .vtu or .pvtu (another collection, or the collection itself) or lies outside its
// directory, two data sets of one step and part.
std::vector<PvdStep> read_pvd_steps(const std::string &path);

// The step `field` chooses: by time (within 1e-9 of the largest time's magnitude, else an
// error listing the times) or by index (negative from the end); an error for one out of range.
std::size_t choose_pvd_step(const std::string &path, const std::vector<PvdStep> &steps,
                            const FieldSelection &field);

// Reads the chosen step: one .vtu or .pvtu part as read_mesh reads it, several joined by the
// position of their shared points. MeshInput::field_detail says which step it is
// ("step 4 of 5, time 0.4: F_4.pvtu"). The memory budget covers all parts together.
MeshInput read_pvd(const std::string &path, const FieldSelection &field = {},
                   const ReadLimits &limits = {});

} // namespace hoct
