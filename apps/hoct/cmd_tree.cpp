// `hoct tree INPUT`: the contour tree, written as JSON and VTP and summarised on the terminal.
#include "commands.hpp"
#include "field_options.hpp"
#include "io/read_limits.hpp"
#include "io/tree_json.hpp"
#include "io/tree_svg_writer.hpp"
#include "io/tree_vtp_writer.hpp"
#include "load_mesh.hpp"
#include "memory_guard.hpp"
#include "output_paths.hpp"
#include "pipeline/compute_tree.hpp"
#include "tree_mpi.hpp"
#include "tree_summary.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>

namespace hoct::cli {
namespace {

struct TreeOptions {
  std::string file, json, vtp, svg, simplify;
  FieldOptions field;
  bool branches = false;
  bool linear = false, augmented = false, force = false, quiet = false, keep_flat = false;
  bool no_timings = false;
  bool simplify_loops = false;
  MergeOption merge;
  int refine = 0;
  int threads = 0;
};

// The flags as a library request.
TreeRequest request_of(const TreeOptions &o) {
  if (o.linear && o.refine > 0)
    throw Error("--linear and --refine exclude each other");
  TreeRequest rq;
  rq.method = o.linear ? TreeMethod::Linear : o.refine > 0 ? TreeMethod::Refine : TreeMethod::Exact;
  rq.refine = o.refine;
  rq.augmented = o.augmented;
  rq.keep_flat = o.keep_flat;
  if (!o.simplify.empty())
    rq.simplify = parse_threshold(o.simplify, "--simplify");
  if (o.simplify_loops && o.simplify.empty())
    throw Error("--simplify-loops needs --simplify THRESHOLD");
  rq.simplify_loops = o.simplify_loops;
  rq.force = o.force;
  rq.threads = o.threads;
  rq.arcs = o.vtp.empty() ? ArcGeometry::None : ArcGeometry::Paths;
  return rq;
}

void run_tree(const TreeOptions &o) {
  Stopwatch total;
  require_distinct_outputs({{"the input", o.file}},
                           {{"--json", o.json}, {"--vtp", o.vtp}, {"--svg", o.svg}});
  TreeRequest rq = request_of(o);
  if (under_mpi()) { // mpirun -np N hoct tree ...
    DistributedTreeRun run{
        o.file,       o.json,  o.svg,     o.vtp, o.field.selection(), o.merge.tolerance(),
        o.no_timings, o.quiet, o.branches};
    run_tree_mpi(run, rq);
    return;
  }
  // Only --linear reads the input's nodes again: elsewhere the mesh holds all the tree needs.
  LoadedMesh lm = load_mesh(o.file, o.field.selection(), /*strict=*/false, o.merge.tolerance(),
                            o.threads, /*keep_input=*/o.linear);
  rq.read_seconds = lm.read_seconds;
  rq.build_seconds = lm.build_seconds;
  if (rq.method == TreeMethod::Refine)
    check_refinement_memory(o.file, lm.mesh.topology.num_cells(), rq.refine);
  // Progress on stderr for large meshes (a phase can take seconds there).
  if (!o.quiet && lm.mesh.topology.num_cells() >= 200000)
    rq.progress = [](const std::string &phase, double s) {
      std::fprintf(stderr, "hoct: %s done (%.2f s)\n", phase.c_str(), s);
    };
  const std::string mesh_line = describe_mesh(o.file, lm.mesh);
  // The linear method releases the checked mesh before its tree, and the input once split.
  const TreeOutcome out = o.linear ? compute_tree(std::move(lm.mesh), rq, std::move(lm.input))
                                   : compute_tree(lm.mesh, rq, &lm.input);
  for (const auto &why : out.warnings)
    std::fprintf(stderr, "hoct: warning: --force: %s\n", why.c_str());
  const TreeResult &tree = out.reported();
  if (!o.svg.empty() && tree.branches.empty())
    throw Error("--svg draws the reduced tree (drop --augmented)");
  if (!o.json.empty())
    write_tree_json(o.json, tree, /*timings=*/!o.no_timings, thread_count(o.threads));
  if (!o.vtp.empty())
    write_tree_vtp(o.vtp, tree);
  if (!o.svg.empty())
    write_tree_svg(o.svg, tree,
                   std::filesystem::path(o.file).filename().string() + ": " + tree.method +
                       (tree.reeb_graph ? " Reeb graph, " : " contour tree, ") +
                       std::to_string(tree.nodes.size()) + " nodes");
  if (!o.quiet)
    print_tree_summary(mesh_line, tree, total.seconds());
  if (o.branches)
    print_branches(tree);
}

} // namespace

void register_tree(CLI::App &app) {
  auto o = std::make_shared<TreeOptions>();
  auto *sub = app.add_subcommand(
      "tree", "Compute the contour tree of a field: exact (default) or piecewise-linear");
  sub->add_option("file", o->file, "Input file (.vtu, .pvtu, .pvd, .msh, .pos)")->required();
  add_field_options(sub, o->field);
  sub->add_flag("--linear", o->linear,
                "Piecewise-linear tree of the input's nodes (each cell split into linear "
                "triangles through its Lagrange nodes)");
  sub->add_option("--refine", o->refine,
                  "Piecewise-linear tree of the exact field on K x K sub-triangles per cell")
      ->check(CLI::Range(1, 1024));
  sub->add_option("--json", o->json, "Write the tree as JSON");
  sub->add_option("--vtp", o->vtp, "Write critical points and arcs as VTK PolyData (.vtp)");
  sub->add_option("--svg", o->svg, "Draw the tree (branch-decomposition layout) as SVG");
  sub->add_flag("--augmented", o->augmented, "Keep regular (degree-2) nodes");
  sub->add_option("--simplify", o->simplify,
                  "Remove leaf branches with persistence below this (absolute, or % of the value "
                  "range, e.g. 0.5%)");
  sub->add_flag("--simplify-loops", o->simplify_loops,
                "With --simplify, also remove the loops of a Reeb graph whose essential pair is "
                "below the threshold (the smallest first, each collapsed to one chain)");
  sub->add_flag("--branches", o->branches, "Print the branch decomposition as an indented list");
  sub->add_flag("--keep-flat", o->keep_flat,
                "Keep the nodes and zero-length arcs that plateaus (equal values) produce, instead "
                "of one node per flat region");
  sub->add_flag("--force,--allow-non-simply-connected", o->force,
                "Compute what is well defined past inverted or folded cells and unmerged "
                "duplicate vertices; the output says so (\"forced\" in the JSON, warnings on "
                "stderr). Not needed for holes, handles or several components: their Reeb "
                "graph is computed without it");
  add_merge_option(sub, o->merge);
  sub->add_option("--threads", o->threads,
                  "Threads for reading, building the mesh, the cell phase, the sweeps and the "
                  "arcs' paths (default: all cores; the result does not depend on it)")
      ->check(CLI::Range(0, 1024));
  sub->add_flag("--no-timings", o->no_timings,
                "Leave the timings (time_* statistics) and a Reeb graph's seam_edges (the size of "
                "the cut, which depends on the run) out of the JSON: the same input then gives "
                "byte-identical files, whatever the thread or MPI rank count");
  sub->add_flag("-q,--quiet", o->quiet, "No summary on the terminal");
  sub->callback([o] { run_tree(*o); });
}

} // namespace hoct::cli
