// `hoct tree INPUT`: the contour tree, written as JSON and VTP and summarised on the terminal.
#include "commands.hpp"
#include "domain_check.hpp"
#include "error.hpp"
#include "io/tree_json.hpp"
#include "io/tree_svg_writer.hpp"
#include "io/tree_vtp_writer.hpp"
#include "load_mesh.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/refinement.hpp"
#include "tree/exact_contour_tree.hpp"
#include "tree_summary.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>

namespace hoct::cli {
namespace {

struct TreeOptions {
  std::string file, scalar, json, vtp, svg, simplify;
  bool branches = false;
  bool linear = false, augmented = false, force = false, quiet = false, keep_flat = false;
  bool no_timings = false;
  MergeOption merge;
  int refine = 0;
  int threads = 0;
};

// "0.01" (absolute) or "0.5%" (of the value range of the tree).
double parse_threshold(const std::string &text, const TreeResult &tree) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  double v = 0;
  std::size_t used = 0;
  try {
    v = std::stod(number, &used);
  } catch (const std::exception &) {
    used = 0;
  }
  if (used != number.size() || number.empty() || !(v >= 0) || !std::isfinite(v))
    throw Error("--simplify: '" + text +
                "' is not a threshold (a number, or a percentage like 0.5%)");
  if (!percent)
    return v;
  const double range = tree.nodes.empty() ? 0 : tree.nodes.back().value - tree.nodes.front().value;
  return v / 100 * range;
}

void run_tree(const TreeOptions &o) {
  using clock = std::chrono::steady_clock;
  if (o.linear && o.refine > 0)
    throw Error("--linear and --refine exclude each other");
  const auto t0 = clock::now();
  // Only --linear reads the input's nodes again: elsewhere the mesh holds all the tree needs.
  const LoadedMesh lm = load_mesh(o.file, o.scalar, /*strict=*/false, o.merge.tolerance(),
                                  o.threads, /*keep_input=*/o.linear);
  const std::vector<std::string> forced = check_domain(lm.mesh, o.file, o.force);
  for (const auto &why : forced)
    std::fprintf(stderr, "hoct: warning: --force: %s\n", why.c_str());
  const auto t1 = clock::now();
  TreeResult tree;
  auto t2 = t1;
  if (o.linear || o.refine > 0) {
    const PlMesh pl = o.linear ? split_lagrange_cells(lm.input) : refine(lm.mesh, o.refine);
    t2 = clock::now();
    tree = pl_contour_tree(pl, o.augmented,
                           o.linear ? "linear" : "refine k=" + std::to_string(o.refine),
                           /*with_graph=*/!o.vtp.empty() && !o.augmented, o.threads);
  } else {
    ExactTreeOptions eo;
    eo.augmented = o.augmented;
    eo.threads = o.threads;
    // Arcs drawn on the surface in the .vtp. Not those of an augmented tree: each joins two
    // consecutive nodes of a contour-tree arc, which may lie anywhere on its band, and a path
    // between them wanders over it (10^5 cubic cells: 4.2 s for the 55,261 arcs, against
    // 0.05 s for the tree); they are drawn straight.
    eo.arc_geometry = !o.vtp.empty() && !o.augmented;
    // Progress on stderr for large meshes (a phase can take seconds there).
    if (!o.quiet && lm.mesh.topology.num_cells() >= 200000)
      eo.progress = [](const std::string &phase, double s) {
        std::fprintf(stderr, "hoct: %s done (%.2f s)\n", phase.c_str(), s);
      };
    tree = exact_contour_tree(lm.mesh, eo);
  }
  const auto t3 = clock::now();
  auto seconds = [](clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  // Plateaus (equal values, ordered by node id) give arcs of length zero and leaf branches of
  // persistence zero: artefacts of the tie-breaking. Each flat region becomes one node unless
  // --keep-flat.
  if (!o.augmented && !o.keep_flat)
    tree = contract_flat(tree);
  if (!o.simplify.empty()) {
    if (o.augmented)
      throw Error("--simplify works on the reduced tree (drop --augmented)");
    tree = simplify_tree(tree, parse_threshold(o.simplify, tree));
  } else {
    decompose_branches(tree);
  }
  tree.forced = forced;
  tree.add_stat("input_cells", static_cast<double>(lm.mesh.topology.num_cells()));
  tree.add_stat("time_read_s", lm.read_seconds);
  tree.add_stat("time_check_s", lm.build_seconds); // the whole mesh build, conversion included
  tree.add_stat("time_bernstein_s", lm.mesh.build_times.field);
  if (t2 != t1)
    tree.add_stat("time_pl_mesh_s", seconds(t1, t2));
  tree.add_stat("time_tree_s", seconds(t2, t3));
  if (o.no_timings) // byte-identical files for identical inputs
    std::erase_if(tree.stats, [](const auto &s) { return s.first.rfind("time_", 0) == 0; });
  if (!o.json.empty())
    write_tree_json(o.json, tree);
  if (!o.vtp.empty()) {
    compute_arc_paths(tree, o.threads);
    write_tree_vtp(o.vtp, tree);
  }
  if (!o.svg.empty()) {
    if (tree.branches.empty())
      throw Error("--svg draws the reduced tree (drop --augmented)");
    write_tree_svg(o.svg, tree,
                   std::filesystem::path(o.file).filename().string() + ": " + tree.method +
                       " contour tree, " + std::to_string(tree.nodes.size()) + " nodes");
  }
  const auto t4 = clock::now();
  if (!o.quiet)
    print_tree_summary(o.file, lm.mesh, tree, seconds(t0, t4));
  if (o.branches)
    print_branches(tree);
}

} // namespace

void register_tree(CLI::App &app) {
  auto o = std::make_shared<TreeOptions>();
  auto *sub = app.add_subcommand(
      "tree", "Compute the contour tree of a field: exact (default) or piecewise-linear");
  sub->add_option("file", o->file, "Input file (.vtu, .msh)")->required();
  sub->add_option("--scalar", o->scalar, "Point-data array / node-data view (default: the first)");
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
  sub->add_flag("--branches", o->branches, "Print the branch decomposition as an indented list");
  sub->add_flag("--keep-flat", o->keep_flat,
                "Keep the nodes and zero-length arcs that plateaus (equal values) produce, instead "
                "of one node per flat region");
  sub->add_flag("--force,--allow-non-simply-connected", o->force,
                "Compute what is well defined when the domain is not one disk or sphere (one "
                "tree per component; the join/split merge where there are holes or handles) or "
                "has inverted cells or unmerged duplicate vertices; the output says so "
                "(\"forced\" in the JSON, warnings on stderr)");
  add_merge_option(sub, o->merge);
  sub->add_option("--threads", o->threads,
                  "Threads for reading, building the mesh, the cell phase, the sweeps and the "
                  "arcs' paths (default: all cores; the result does not depend on it)")
      ->check(CLI::Range(0, 1024));
  sub->add_flag("--no-timings", o->no_timings,
                "Leave the timings (time_* statistics) out of the JSON: the same input then gives "
                "byte-identical files, whatever the thread count");
  sub->add_flag("-q,--quiet", o->quiet, "No summary on the terminal");
  sub->callback([o] { run_tree(*o); });
}

} // namespace hoct::cli
