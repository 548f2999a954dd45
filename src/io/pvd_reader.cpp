#include "io/pvd_reader.hpp"

#include "io/collection_xml.hpp"
#include "io/piece_join.hpp"
#include "io/pvtu_reader.hpp"
#include "io/vtu_reader.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>

namespace hoct {

namespace {

std::optional<double> parse_time(const std::string &path, const pugi::xml_attribute &a,
                                 std::size_t index) {
  if (!a)
    return std::nullopt;
  const char *s = a.as_string();
  const char *end = s + std::strlen(s);
  while (s < end && std::isspace(static_cast<unsigned char>(*s)))
    ++s;
  while (end > s && std::isspace(static_cast<unsigned char>(end[-1])))
    --end;
  double t = 0;
  const auto r = std::from_chars(s, end, t);
  if (s == end || r.ec != std::errc() || r.ptr != end || !std::isfinite(t))
    throw InputError(path + ": DataSet " + std::to_string(index) + ": timestep '" + a.as_string() +
                     "' is not a finite number");
  return t;
}

} // namespace

std::vector<PvdStep> read_pvd_steps(const std::string &path) {
  CollectionXml xml;
  load_collection_xml(path, "Collection", xml);
  struct Entry {
    std::optional<double> time;
    std::string part, listed, file;
    std::size_t index;
  };
  std::vector<Entry> entries;
  for (const pugi::xml_node d : xml.element.children("DataSet")) {
    const std::size_t index = entries.size();
    Entry e{parse_time(path, d.attribute("timestep"), index),
            std::string(d.attribute("group").as_string()) + "/" + d.attribute("part").as_string(),
            d.attribute("file").as_string(), "", index};
    e.file = collection_member(path, e.listed, "DataSet " + std::to_string(index) + " file",
                               ".vtu .pvtu");
    if (!entries.empty() && e.time.has_value() != entries.front().time.has_value())
      throw InputError(path + ": DataSet " + std::to_string(index) +
                       (e.time ? " has a timestep and DataSet 0 has none"
                               : " has no timestep and DataSet 0 has one") +
                       ": which step is which is ambiguous");
    entries.push_back(std::move(e));
  }
  if (entries.empty())
    throw InputError(path + ": no <DataSet> in <Collection>: the collection is empty");
  std::stable_sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) {
    return a.time.value_or(0) < b.time.value_or(0);
  });
  std::vector<PvdStep> steps;
  std::map<std::string, std::size_t> parts; // of the current step: part -> DataSet
  for (const Entry &e : entries) {
    if (steps.empty() || steps.back().time != e.time) {
      steps.push_back({e.time, {}, {}});
      parts.clear();
    }
    const auto [it, fresh] = parts.emplace(e.part, e.index);
    if (!fresh)
      throw InputError(path + ": DataSets " + std::to_string(it->second) + " and " +
                       std::to_string(e.index) + " are both part '" +
                       e.part.substr(e.part.find('/') + 1) + "'" +
                       (e.time ? " of timestep " + format_time(*e.time) : std::string()) +
                       ": which one holds the step is ambiguous");
    steps.back().listed.push_back(e.listed);
    steps.back().files.push_back(e.file);
  }
  return steps;
}

std::size_t choose_pvd_step(const std::string &path, const std::vector<PvdStep> &steps,
                            const FieldSelection &field) {
  if (field.time && !steps.front().time)
    throw InputError(path + ": --time " + format_time(*field.time) +
                     ": the collection's data sets have no timestep (choose with --step)");
  std::vector<std::optional<double>> times;
  for (const PvdStep &s : steps)
    times.push_back(s.time);
  return choose_step(path, times, field, "the collection");
}

MeshInput read_pvd(const std::string &path, const FieldSelection &field, const ReadLimits &limits) {
  const std::vector<PvdStep> steps = read_pvd_steps(path);
  const std::size_t chosen = choose_pvd_step(path, steps, field);
  const PvdStep &step = steps[chosen];
  std::string detail = step_description(chosen, steps.size(), step.time) + ": " +
                       (step.listed.size() == 1 ? step.listed.front()
                                                : std::to_string(step.listed.size()) + " parts");
  // The parts hold one step each: the choice is made.
  FieldSelection one_step = field;
  one_step.step = -1;
  one_step.time.reset();
  std::vector<FilePiece> parts(step.files.size());
  ReadLimits budget = limits;
  for (std::size_t k = 0; k < step.files.size(); ++k) {
    const std::string &file = step.files[k];
    FilePiece &p = parts[k];
    p.file = file;
    try {
      if (lowercase_extension(file) == ".pvtu")
        p.input = read_pvtu(file, one_step, budget);
      else if (step.files.size() == 1)
        p.input = read_vtu(file, one_step, budget); // alone: as read_mesh reads it
      else
        p.input = read_vtu_piece(file, one_step, budget,
                                 {.global_ids_name = {}, .allow_empty = true}, p.arrays);
    } catch (const InputError &e) {
      throw InputError(path + ": " + detail.substr(0, detail.find(':')) +
                       (step.files.size() > 1 ? ", part " + std::to_string(k) : std::string()) +
                       ": " + e.what());
    }
    budget.prior_points += p.input.points.size();
    budget.prior_cells += p.input.num_cells();
    budget.prior_cell_nodes += p.input.cell_nodes.size();
  }
  MeshInput m;
  if (parts.size() == 1) {
    m = std::move(parts.front().input);
  } else {
    std::vector<std::string> warnings;
    for (FilePiece &p : parts)
      for (std::string &w : p.input.warnings)
        warnings.push_back(std::move(w));
    m = join_pieces(std::move(parts), path, /*by_ids=*/false, limits.threads);
    m.warnings = std::move(warnings);
  }
  m.source = path;
  m.field_detail = "(" + detail + ")";
  return m;
}

} // namespace hoct
