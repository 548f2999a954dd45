#include "pipeline/compute_tree.hpp"

#include "exact/exact_contour_tree.hpp"
#include "mesh/cut_surface.hpp"
#include "pipeline/domain_check.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/pl_mesh.hpp"
#include "pl/refinement.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

namespace hoct {
namespace {

void check_request(const TreeRequest &rq, const MeshInput *input) {
  if (rq.method == TreeMethod::Refine && (rq.refine < 1 || rq.refine > 1024))
    throw Error("refine: K must be between 1 and 1024, not " + std::to_string(rq.refine));
  if (rq.method == TreeMethod::Linear && input == nullptr)
    throw Error("the linear method needs the mesh's Lagrange nodes as read (the input)");
  if (rq.simplify && rq.augmented)
    throw Error("simplification works on the reduced tree (drop --augmented)");
  if (rq.simplify_loops && !rq.simplify)
    throw Error("removing loops needs a threshold (--simplify)");
  if (rq.threads < 0)
    throw Error("threads must be 0 (all cores) or more, not " + std::to_string(rq.threads));
}

// An augmented tree's arcs join consecutive nodes of a contour-tree arc, which may lie
// anywhere on its band: a path between them would wander over it. They are drawn straight.
bool wants_graph(const TreeRequest &rq) { return rq.arcs != ArcGeometry::None && !rq.augmented; }

// The PL tree of the input's own nodes (the linear method). With `release` (the input, owned),
// the input is released once split.
TreeResult linear_tree(const MeshInput &input, const TreeRequest &rq, bool reeb, int threads,
                       MeshInput *release = nullptr) {
  Stopwatch clock;
  const PlMesh pl = split_lagrange_cells(input);
  if (release)
    *release = MeshInput{};
  const double pl_seconds = clock.lap();
  if (rq.progress)
    rq.progress("piecewise-linear mesh", pl_seconds);
  TreeResult tree =
      pl_contour_tree(pl, rq.augmented, method_name(rq), wants_graph(rq), threads, reeb);
  tree.stats.time.pl_mesh = pl_seconds;
  tree.stats.time.tree = clock.seconds(); // (the split is time_pl_mesh_s, apart)
  return tree;
}

// The tree by the requested method, its phases timed.
TreeResult method_tree(const Mesh &mesh, const TreeRequest &rq, const MeshInput *input,
                       int threads) {
  const bool graph = wants_graph(rq);
  // Not a disk or a sphere: the Reeb graph, from the surface cut open into disks (the PL mesh
  // of the linear and refine methods covers the same surface).
  const bool reeb = !domain_shape(mesh.topology).empty();
  if (rq.method == TreeMethod::Linear)
    return linear_tree(*input, rq, reeb, threads);
  Stopwatch clock;
  if (rq.method == TreeMethod::Exact) {
    ExactTreeOptions eo;
    eo.augmented = rq.augmented;
    eo.fallback_refinement = rq.fallback_refinement;
    eo.threads = threads;
    eo.arc_geometry = graph;
    eo.progress = rq.progress;
    const std::vector<int64_t> cut_edges =
        reeb ? cut_graph_edges(mesh.topology) : std::vector<int64_t>{};
    std::optional<CutSurface> cut;
    if (!cut_edges.empty()) {
      cut = cut_open(mesh, cut_edges);
      eo.cut = &*cut;
    }
    const double cut_seconds = clock.lap();
    TreeResult tree = exact_contour_tree(cut ? cut->mesh : mesh, eo);
    tree.reeb_graph = reeb;
    if (reeb) {
      tree.stats.time.cut = cut_seconds;
      // Spheres and disks only (several components): nothing cut, nothing glued.
      tree.stats.seam_edges = tree.stats.seam_edges.value_or(0);
      tree.stats.seam_paths_nonmonotone = tree.stats.seam_paths_nonmonotone.value_or(0);
    }
    tree.stats.time.tree = cut_seconds + clock.seconds();
    return tree;
  }
  const PlMesh pl = refine(mesh, rq.refine);
  const double pl_seconds = clock.lap();
  if (rq.progress)
    rq.progress("piecewise-linear mesh", pl_seconds);
  TreeResult tree = pl_contour_tree(pl, rq.augmented, method_name(rq), graph, threads, reeb);
  tree.stats.time.pl_mesh = pl_seconds;
  tree.stats.time.tree = clock.seconds();
  return tree;
}

// The nodes' cells as the input's (a quadrilateral, not one of its two triangles: mesh/cell_split).
// A tree of the input's own linear cells (the linear method) names them already.
void to_input_cells(TreeResult &tree, const CellOrigins &origins) {
  if (origins.identity())
    return;
  for (TreeNode &n : tree.nodes)
    if (n.cell >= 0) {
      const CellPlace p = origins.to_input(n.cell, n.uv);
      n.cell = p.cell;
      n.uv = p.uv;
    }
}

} // namespace

std::string method_name(const TreeRequest &rq) {
  switch (rq.method) {
  case TreeMethod::Exact:
    return "exact";
  case TreeMethod::Linear:
    return "linear";
  case TreeMethod::Refine:
    return "refine k=" + std::to_string(rq.refine);
  }
  return "?";
}

namespace {

// What the rest takes from the mesh (the origins by reference: the mesh must outlive their use).
TreeContext context_of(const Mesh &mesh, const TreeRequest &rq, std::vector<std::string> warnings) {
  TreeContext context;
  context.warnings = std::move(warnings);
  context.fingerprint = mesh.fingerprint;
  context.input_cells =
      mesh.origins.identity() ? mesh.topology.num_cells() : mesh.origins.num_input_cells();
  context.build_times = mesh.build_times;
  context.cells_split = !mesh.origins.identity();
  context.precision = mesh.field.precision();
  if (rq.method != TreeMethod::Linear)
    context.origins = &mesh.origins;
  return context;
}

} // namespace

TreeOutcome compute_tree(const Mesh &mesh, const TreeRequest &rq, const MeshInput *input) {
  check_request(rq, input);
  std::vector<std::string> warnings = check_domain(mesh, rq.force);
  const int threads = thread_count(rq.threads);
  TreeResult tree = method_tree(mesh, rq, input, threads);
  return finish_tree(std::move(tree), rq, context_of(mesh, rq, std::move(warnings)));
}

TreeOutcome compute_tree(Mesh &&mesh, const TreeRequest &rq, MeshInput &&input) {
  if (rq.method != TreeMethod::Linear) {
    const Mesh owned = std::move(mesh);
    const MeshInput nodes = std::move(input);
    return compute_tree(owned, rq, &nodes);
  }
  check_request(rq, &input);
  TreeContext context = context_of(mesh, rq, check_domain(mesh, rq.force));
  const bool reeb = !domain_shape(mesh.topology).empty();
  mesh = Mesh{};
  TreeResult tree = linear_tree(input, rq, reeb, thread_count(rq.threads), &input);
  return finish_tree(std::move(tree), rq, context);
}

TreeOutcome finish_tree(TreeResult tree, const TreeRequest &rq, const TreeContext &context) {
  TreeOutcome out;
  out.warnings = context.warnings;
  const int threads = thread_count(rq.threads);
  Stopwatch clock;
  // Plateaus (equal values, ordered by node id) give arcs of length zero and leaf branches of
  // persistence zero: artefacts of the tie-breaking. Each flat region becomes one node.
  if (!rq.augmented && !rq.keep_flat)
    tree = contract_flat(std::move(tree));
  else
    decompose_branches(tree);
  tree.stats.time.branches = clock.lap();
  tree.forced = out.warnings;
  tree.input = context.fingerprint;
  tree.stats.input_cells = context.input_cells;
  tree.stats.time.read = rq.read_seconds;
  tree.stats.time.check = rq.build_seconds;
  const MeshBuildTimes &bt = context.build_times;
  tree.stats.time.bernstein = bt.field;
  if (context.cells_split)
    tree.stats.time.cell_split = bt.cell_split;
  tree.stats.time.topology = bt.topology;
  tree.stats.time.geometry = bt.geometry;
  tree.stats.time.geometry_checks = bt.geometry_checks;
  if (rq.simplify) {
    const double range =
        tree.nodes.empty() ? 0 : tree.nodes.back().value - tree.nodes.front().value;
    clock.lap();
    out.simplified = simplify_tree(tree, rq.simplify->absolute(range), rq.simplify_loops);
    // Its branches: the whole tree's, then simplified and decomposed again.
    out.simplified->stats.time.branches = *tree.stats.time.branches + clock.lap();
    out.simplified->forced = out.warnings;
    set_precision(*out.simplified, context.precision);
  }
  set_precision(tree, context.precision);
  clock.lap();
  const bool all_paths = rq.arcs == ArcGeometry::AllPaths,
             paths = all_paths || rq.arcs == ArcGeometry::Paths;
  if (all_paths || (paths && !out.simplified))
    compute_arc_paths(tree, threads);
  if (out.simplified && paths)
    compute_arc_paths(*out.simplified, threads);
  if (paths) {
    tree.stats.time.arc_paths = clock.lap();
    if (out.simplified)
      out.simplified->stats.time.arc_paths = tree.stats.time.arc_paths;
  }
  if (context.origins) {
    to_input_cells(tree, *context.origins);
    if (out.simplified)
      to_input_cells(*out.simplified, *context.origins);
  }
  out.tree = std::move(tree);
  return out;
}

} // namespace hoct
