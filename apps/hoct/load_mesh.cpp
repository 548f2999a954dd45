#include "load_mesh.hpp"

#include "io/read_mesh.hpp"
#include "memory_guard.hpp"
#include "mesh/duplicate_points.hpp"
#include "mesh/gll_nodes.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include <cstdio>

namespace hoct::cli {

LoadedMesh load_mesh(const std::string &path, const FieldSelection &field, bool strict,
                     double merge_tolerance, int threads, bool keep_input) {
  LoadedMesh r;
  Stopwatch clock;
  ReadLimits limits = read_limits();
  limits.threads = thread_count(threads);
  r.input = read_mesh(path, field, limits, &r.contents);
  for (const std::string &w : r.input.warnings)
    std::fprintf(stderr, "hoct: warning: %s\n", w.c_str());
  if (merge_tolerance >= 0) {
    const MergeReport m = merge_duplicate_points(r.input, merge_tolerance, thread_count(threads));
    if (m.merged_points > 0)
      std::fprintf(stderr,
                   "hoct: merged %lld duplicate point(s) of %s (tolerance %g of the "
                   "bounding-box diagonal)\n",
                   static_cast<long long>(m.merged_points), path.c_str(), merge_tolerance);
  }
  const GllResampling gll = resample_gll_cells(r.input);
  print_gll_notes(path, gll);
  r.read_seconds = clock.lap();
  const MeshBuildOptions build{.throw_on_error = strict, .threads = thread_count(threads)};
  r.mesh = keep_input ? build_mesh(r.input, build) : build_mesh(std::move(r.input), build);
  r.build_seconds = clock.lap();
  return r;
}

void print_gll_notes(const std::string &path, const GllResampling &resampled) {
  for (const std::string &note : gll_notes(resampled))
    std::fprintf(stderr, "hoct: note: %s: %s\n", path.c_str(), note.c_str());
}

void add_merge_option(CLI::App *sub, MergeOption &merge) {
  merge.option = sub->add_option("--merge-duplicates", merge.text,
                                 "Merge points at the same position before building the mesh "
                                 "(--merge-duplicates=TOL: within TOL of the bounding-box "
                                 "diagonal; default 1e-9)")
                     ->expected(0, 1);
}

double MergeOption::tolerance() const {
  if (option == nullptr || option->count() == 0)
    return -1;
  if (text.empty())
    return 1e-9;
  double v = -1;
  std::size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception &) {
    used = 0;
  }
  if (used != text.size() || !(v >= 0 && v <= 0.1))
    throw Error("--merge-duplicates: '" + text +
                "' is not a tolerance between 0 and 0.1 (write --merge-duplicates=TOL)");
  return v;
}

} // namespace hoct::cli
