// `hoct check TREE.json INPUT`: verifies a contour tree written by `hoct tree --json` against the
// mesh and field it was computed from (analysis/tree_check.hpp): tree-ness, Euler relation, order,
// node values and positions, types versus degrees and versus samples of the field.
#include "analysis/tree_check.hpp"
#include "commands.hpp"
#include "field_options.hpp"
#include "io/tree_json.hpp"
#include "load_mesh.hpp"
#include "tree_input.hpp"
#include "tree_summary.hpp"
#include "util/error.hpp"

#include <cstdio>
#include <iostream>
#include <memory>

namespace hoct::cli {
namespace {

struct CheckOptions {
  std::string tree, file;
  FieldOptions field;
  bool verbose = false;
  double value_tolerance = 1e-9;
  MergeOption merge;
};

void run_check(const CheckOptions &o) {
  const TreeResult tree = read_tree_json(o.tree);
  // Not strict: a tree computed with --force on an invalid domain can still be checked.
  const LoadedMesh lm =
      load_mesh(o.file, o.field.selection(), /*strict=*/false, o.merge.tolerance());
  if (!lm.mesh.complete)
    throw Error(o.file + ": the mesh is too broken to check a tree against:\n" +
                lm.mesh.problems.summary());
  require_tree_of_mesh(o.tree, tree, o.file, lm.mesh, "--scalar and --merge-duplicates");
  TreeCheckOptions opt;
  opt.value_tolerance = o.value_tolerance;
  // The PL trees (--linear, --refine) are trees of another field: only their structure, values
  // and positions are checked, not their types against the exact field.
  opt.check_types = tree.method == "exact";
  const TreeCheckReport r = check_tree(tree, lm.mesh, opt);
  std::printf("%s against %s: %zu nodes, %zu arcs (%s %s%s)\n", o.tree.c_str(), o.file.c_str(),
              tree.nodes.size(), tree.arcs.size(), tree.method.c_str(), graph_kind(tree).c_str(),
              opt.check_types ? "" : "; types not compared with the exact field");
  if (o.verbose)
    for (const auto &s : r.skipped)
      std::printf("skipped: %s\n", s.message.c_str());
  std::fputs(r.summary(o.verbose ? r.failures.size() : 20).c_str(), stdout);
  if (!r.ok()) {
    std::fflush(stdout);
    std::fprintf(stderr, "hoct: check failed: %zu finding(s)\n", r.failures.size());
    throw CLI::RuntimeError(1);
  }
  std::printf("OK\n");
}

} // namespace

void register_check(CLI::App &app) {
  auto o = std::make_shared<CheckOptions>();
  auto *sub = app.add_subcommand(
      "check",
      "Check a contour tree (hoct tree --json) against its input: tree-ness, Euler "
      "relation, values, positions and node types (exit 1 with the findings if any fails)");
  sub->add_option("tree", o->tree, "Tree file written by hoct tree --json")->required();
  sub->add_option("file", o->file, "The input mesh (.vtu, .msh) the tree was computed from")
      ->required();
  add_field_options(sub, o->field);
  sub->add_option("--value-tolerance", o->value_tolerance,
                  "Allowed |value - field| relative to the value range (default 1e-9)")
      ->check(CLI::PositiveNumber);
  add_merge_option(sub, o->merge);
  sub->add_flag("-v,--verbose", o->verbose, "List every failure and every skipped node");
  sub->callback([o] { run_check(*o); });
}

} // namespace hoct::cli
