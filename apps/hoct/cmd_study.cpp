// `hoct study INPUT --refine 1,2,4,8,16`: the exact tree against PL trees of refinements.
#include "analysis/case_study.hpp"
#include "commands.hpp"
#include "field_options.hpp"
#include "load_mesh.hpp"
#include "output_paths.hpp"
#include "study_writers.hpp"
#include "util/error.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace hoct::cli {
namespace {

struct StudyCmdOptions {
  std::string file, csv, json, svg, threshold = "1%";
  FieldOptions field;
  std::vector<int> levels = {1, 2, 4, 8, 16};
  int threads = 0;
};

void run_study(const StudyCmdOptions &o) {
  require_distinct_outputs({{"the input", o.file}},
                           {{"--csv", o.csv}, {"--json", o.json}, {"--svg", o.svg}});
  const LoadedMesh lm = load_mesh(o.file, o.field.selection(), /*strict=*/true);
  StudyOptions so;
  so.levels = o.levels;
  so.threads = o.threads;
  const double range = lm.mesh.field.max_value() - lm.mesh.field.min_value();
  const bool percent = !o.threshold.empty() && o.threshold.back() == '%';
  try {
    so.feature_threshold =
        std::stod(percent ? o.threshold.substr(0, o.threshold.size() - 1) : o.threshold);
  } catch (const std::exception &) {
    throw Error("study: --threshold '" + o.threshold + "' is not a number or percentage");
  }
  if (percent)
    so.feature_threshold *= range / 100;
  for (int k : so.levels)
    if (k < 1 || k > 256)
      throw Error("study: refinement levels must be between 1 and 256");
  const auto rows = case_study(lm.mesh, so);
  std::printf("%s: exact tree vs PL trees of k x k refinements (features: extrema with "
              "persistence >= %.4g)\n",
              o.file.c_str(), so.feature_threshold);
  std::printf("%-8s %10s %6s %6s %7s %12s %12s %12s %7s %9s %9s\n", "method", "triangles", "min",
              "max", "saddle", "bottleneck", "mean dist", "max dist", "missed", "spurious",
              "time (s)");
  for (const auto &r : rows) {
    const std::string name = r.k == 0 ? "exact" : "PL k=" + std::to_string(r.k);
    std::printf("%-8s %10lld %6lld %6lld %7lld %12.4g %12.4g %12.4g %7lld %9lld %9.4f\n",
                name.c_str(), static_cast<long long>(r.triangles),
                static_cast<long long>(r.counts[0]), static_cast<long long>(r.counts[1]),
                static_cast<long long>(r.counts[2]), r.bottleneck, r.mean_distance, r.max_distance,
                static_cast<long long>(r.missed), static_cast<long long>(r.spurious), r.seconds);
  }
  if (!o.csv.empty())
    write_study_csv(o.csv, rows);
  if (!o.json.empty())
    write_study_json(o.json, rows, o.file, so.feature_threshold);
  if (!o.svg.empty())
    write_study_svg(o.svg, rows,
                    std::filesystem::path(o.file).filename().string() +
                        ": PL approximations against the exact contour tree");
}

} // namespace

void register_study(CLI::App &app) {
  auto o = std::make_shared<StudyCmdOptions>();
  auto *sub = app.add_subcommand("study", "Case study (thesis 5.5): the exact tree against the "
                                          "PL trees of uniform refinements");
  sub->add_option("file", o->file, "Input file (.vtu, .pvtu, .pvd, .msh, .pos)")->required();
  add_field_options(sub, o->field);
  sub->add_option("--refine", o->levels, "Refinement levels, e.g. 1,2,4,8,16")->delimiter(',');
  sub->add_option("--threshold", o->threshold,
                  "Persistence of a feature (absolute or % of the value range; default 1%)");
  sub->add_option("--csv", o->csv, "Write the table as CSV");
  sub->add_option("--json", o->json, "Write the table as JSON");
  sub->add_option("--svg", o->svg, "Draw error and missed features against triangles (SVG)");
  sub->add_option("--threads", o->threads, "Threads for the exact tree (default: all cores)");
  sub->callback([o] { run_study(*o); });
}

} // namespace hoct::cli
