// `hoct info FILE`: what the file holds and whether hoct can compute its contour tree.
#include "commands.hpp"
#include "field_options.hpp"
#include "io/collection_xml.hpp"
#include "io/pvd_reader.hpp"
#include "load_mesh.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <map>
#include <memory>

namespace hoct::cli {
namespace {

struct InfoOptions {
  std::string file;
  FieldOptions field;
  MergeOption merge;
  bool json = false;
};

std::string domain_kind(const Topology &t) {
  if (t.components() != 1)
    return std::to_string(t.components()) + " separate components";
  if (t.euler_characteristic() == 1 && t.boundary_loops() == 1)
    return "disk";
  if (t.euler_characteristic() == 2 && t.boundary_loops() == 0)
    return "sphere";
  return "not simply connected (Euler characteristic " + std::to_string(t.euler_characteristic()) +
         ", " + std::to_string(t.boundary_loops()) + " boundary loops)";
}

int run_info(const InfoOptions &o) {
  // A collection's steps, listed with the one read.
  std::vector<PvdStep> steps;
  if (lowercase_extension(o.file) == ".pvd")
    steps = read_pvd_steps(o.file);
  const LoadedMesh lm =
      load_mesh(o.file, o.field.selection(), /*strict=*/false, o.merge.tolerance());
  const Mesh &m = lm.mesh;
  std::map<int, int64_t> degrees;
  for (int64_t c = 0; c < m.field.num_cells(); ++c)
    ++degrees[m.field.input_degree(c)];
  const bool ok = m.complete && !m.problems.has_errors();
  const std::string geometry = !m.complete
                                   ? "unknown"
                                   : std::string(m.geometry.planar() ? "planar" : "surface") +
                                         (m.geometry.curved_cells() > 0 ? "-curved" : "-straight");

  if (o.json) {
    nlohmann::ordered_json j;
    j["file"] = o.file;
    j["field"] = m.field_name;
    if (!m.field_detail.empty())
      j["field_detail"] = m.field_detail;
    if (!lm.contents.fields.empty()) {
      nlohmann::ordered_json views = nlohmann::ordered_json::array();
      for (const FileField &f : lm.contents.fields) {
        nlohmann::ordered_json steps = nlohmann::ordered_json::array();
        for (const FileFieldStep &s : f.steps)
          steps.push_back(
              {{"tag", s.tag}, {"time", s.time ? nlohmann::ordered_json(*s.time) : nullptr}});
        views.push_back(
            {{"name", f.name}, {"kind", f.kind}, {"components", f.components}, {"steps", steps}});
      }
      j["views"] = views;
    }
    if (!steps.empty()) {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (std::size_t i = 0; i < steps.size(); ++i) {
        nlohmann::ordered_json s;
        s["index"] = i;
        s["time"] = steps[i].time ? nlohmann::ordered_json(*steps[i].time) : nullptr;
        s["files"] = steps[i].listed;
        list.push_back(s);
      }
      j["steps"] = list;
    }
    j["cells"] = m.complete ? m.num_input_cells() : 0;
    j["points"] = m.num_points;
    nlohmann::ordered_json deg = nlohmann::ordered_json::object();
    for (auto [d, n] : degrees)
      deg[std::to_string(d)] = n;
    j["degrees"] = deg; // of the triangles the tree is computed on
    nlohmann::ordered_json kinds = nlohmann::ordered_json::array();
    for (const auto &[key, n] : m.input_cell_kinds)
      kinds.push_back({{"kind", cell_kind_name(key.first)}, {"degree", key.second}, {"count", n}});
    j["cell_kinds"] = kinds;
    if (m.complete && !m.origins.identity())
      j["triangles"] = m.topology.num_cells();
    if (m.complete) {
      j["vertices"] = m.topology.num_vertices();
      j["edges"] = m.topology.num_edges();
      j["boundary_edges"] = m.topology.boundary_edges();
      j["euler_characteristic"] = m.topology.euler_characteristic();
      j["boundary_loops"] = m.topology.boundary_loops();
      j["components"] = m.topology.components();
      j["domain"] = domain_kind(m.topology);
      j["value_range"] = {m.field.min_value(), m.field.max_value()};
      j["precision"] = m.field.precision();
      j["geometry"] = geometry;
      j["curved_cells"] = m.geometry.curved_cells();
      j["bounds"] = m.geometry.bounds();
    }
    nlohmann::ordered_json probs = nlohmann::ordered_json::array();
    for (const auto &[kind, k] : m.problems.kinds())
      probs.push_back({{"kind", to_string(kind)},
                       {"severity", k.severity == Severity::Error ? "error" : "warning"},
                       {"count", k.count},
                       {"examples", k.examples}});
    j["problems"] = probs;
    j["valid"] = ok;
    j["timings"] = {{"read", lm.read_seconds}, {"build", lm.build_seconds}};
    std::cout << j.dump(2) << "\n";
    if (!ok)
      std::fprintf(stderr, "hoct: %s: the mesh is not valid (see \"problems\")\n", o.file.c_str());
    return ok ? 0 : 1;
  }

  std::printf("file:        %s\n", o.file.c_str());
  if (!steps.empty()) {
    std::printf("steps:       %zu (by default the last; choose with --step N or --time T)\n",
                steps.size());
    // A long series: its first and last steps (--json lists all).
    constexpr std::size_t kShown = 20;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (steps.size() > 2 * kShown && i == kShown) {
        std::printf("  ... (%zu more)\n", steps.size() - 2 * kShown);
        i = steps.size() - kShown - 1;
        continue;
      }
      std::string files;
      for (const std::string &f : steps[i].listed)
        files += (files.empty() ? "" : ", ") + f;
      std::printf("  step %zu: %s%s\n", i,
                  steps[i].time ? ("time " + format_time(*steps[i].time) + ", ").c_str() : "",
                  files.c_str());
    }
  }
  std::printf("field:       %s%s\n", m.field_name.c_str(),
              m.field_detail.empty() ? "" : (" " + m.field_detail).c_str());
  if (!lm.contents.fields.empty()) {
    std::printf("fields:\n");
    for (const FileField &f : lm.contents.fields) {
      std::string times;
      for (std::size_t i = 0; i < f.steps.size(); ++i) {
        if (i == 12) {
          times += ", ...";
          break;
        }
        char buf[40];
        if (f.steps[i].time)
          std::snprintf(buf, sizeof buf, "%.9g", *f.steps[i].time);
        times += (i ? ", " : "") + (f.steps[i].time ? std::string(buf) : std::string("none"));
      }
      std::printf("  %s: %s, %lld component%s, %zu time step%s (times %s)\n", f.name.c_str(),
                  f.kind.c_str(), static_cast<long long>(f.components),
                  f.components == 1 ? "" : "s", f.steps.size(), f.steps.size() == 1 ? "" : "s",
                  times.c_str());
    }
  }
  if (m.complete) {
    std::printf("cells:       %lld (%s)\n", static_cast<long long>(m.num_input_cells()),
                m.describe_input_cells().c_str());
    if (!m.origins.identity()) {
      std::string tris;
      for (auto [d, n] : degrees)
        tris += (tris.empty() ? "" : ", ") + std::string("degree ") + std::to_string(d) + ": " +
                std::to_string(n);
      std::printf("             computed on %lld triangles (%s): each quadrilateral of order p "
                  "cut into two of degree 2p, exactly\n",
                  static_cast<long long>(m.topology.num_cells()), tris.c_str());
    }
    std::printf("points:      %lld (vertices %lld, edges %lld, boundary edges %lld)\n",
                static_cast<long long>(m.num_points),
                static_cast<long long>(m.topology.num_vertices()),
                static_cast<long long>(m.topology.num_edges()),
                static_cast<long long>(m.topology.boundary_edges()));
    std::printf("geometry:    %s (%lld curved cells)\n", geometry.c_str(),
                static_cast<long long>(m.geometry.curved_cells()));
    std::printf("topology:    Euler characteristic %lld, %lld boundary loop(s), %lld "
                "component(s): %s\n",
                static_cast<long long>(m.topology.euler_characteristic()),
                static_cast<long long>(m.topology.boundary_loops()),
                static_cast<long long>(m.topology.components()), domain_kind(m.topology).c_str());
    std::printf("values:      [%.17g, %.17g]\n", m.field.min_value(), m.field.max_value());
    std::printf("precision:   %.3g (the smallest persistence these values resolve)\n",
                m.field.precision());
  } else {
    std::printf("points:      %lld\n", static_cast<long long>(m.num_points));
  }
  std::printf("timings:     read %.3f s, checks %.3f s\n", lm.read_seconds, lm.build_seconds);
  if (m.problems.empty())
    std::printf("problems:    none\n");
  else
    std::printf("problems:\n%s", m.problems.summary().c_str());
  return ok ? 0 : 1;
}

} // namespace

void register_info(CLI::App &app) {
  auto o = std::make_shared<InfoOptions>();
  auto *sub = app.add_subcommand("info", "Describe a mesh file: cells, degrees, topology, value "
                                         "range, geometry and any problems (exit 1 if invalid)");
  sub->add_option("file", o->file, "Input file (.vtu, .pvtu, .pvd, .msh, .pos)")->required();
  add_field_options(sub, o->field);
  sub->add_flag("--json", o->json, "Print JSON instead of text");
  add_merge_option(sub, o->merge);
  sub->callback([o] {
    const int rc = run_info(*o);
    if (rc != 0)
      throw CLI::RuntimeError(rc);
  });
}

} // namespace hoct::cli
