#include "exact/exact_contour_tree.hpp"

#include "exact/exact_arc_graph.hpp"
#include "exact/exact_graph_build.hpp"
#include "exact/graph_sweeps.hpp"
#include "exact/seam_gluing.hpp"
#include "util/page_pool.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#include "tree/stand_in_contraction.hpp"

#include <algorithm>
#include <unordered_map>

namespace hoct {
namespace {

// The tree's nodes where they lie in the mesh, its arcs and persistence pairs. On a surface cut
// open, a node glued from copies of one point (`links`: seam_links) is placed as the uncut mesh
// places it: in the lowest cell among them, a fallback node if any of them is.
TreeResult tree_result(const Mesh &mesh, const EdgeNodes &en, const ExactGraph &g,
                       const ContourTree &ct, bool augmented,
                       std::span<const std::array<int64_t, 2>> links) {
  std::unordered_map<int64_t, int64_t> parent;
  const auto find = [&](int64_t x) {
    auto it = parent.find(x);
    if (it == parent.end())
      return x;
    while (it->second != x) {
      x = it->second;
      it = parent.find(x);
    }
    return x;
  };
  for (const auto &[a, b] : links) {
    parent.try_emplace(a, a);
    parent.try_emplace(b, b);
    const int64_t x = find(a), y = find(b);
    parent[std::max(x, y)] = std::min(x, y);
  }
  std::unordered_map<int64_t, std::vector<int64_t>> copies; // by root
  for (const auto &[id, up] : parent)
    copies[find(id)].push_back(id);
  return tree_result_of(ct, "exact", augmented, [&](TreeNode &n) {
    NodeSource where = g.source(mesh.topology, en, n.graph_node);
    if (const auto it = copies.find(find(n.graph_node)); it != copies.end()) {
      bool fallback = false;
      int64_t lowest = -1;
      for (const int64_t id : it->second) {
        const NodeSource s = g.source(mesh.topology, en, id);
        fallback = fallback || s.fallback;
        if (lowest < 0 || s.cell < where.cell || (s.cell == where.cell && id < lowest)) {
          where = s;
          lowest = id;
        }
      }
      where.fallback = fallback;
    }
    n.cell = where.cell;
    n.uv = where.uv;
    n.location = where.location;
    n.fallback = where.fallback;
    n.position = mesh.geometry.position(n.cell, n.uv[0], n.uv[1]);
  });
}

// The arcs of the fallback cells' PL stand-in no longer than twice its certified distance from
// the field there, contracted (tree/stand_in_contraction.hpp); returns how many. Augmented trees
// keep them (their regular nodes would be spliced out).
int64_t contract_stand_in(const DegenerateCells &degenerate, bool augmented, ContourTree &ct) {
  if (augmented || degenerate.max_error <= 0)
    return 0;
  const auto &errors = degenerate.node_error;
  std::vector<double> slack(static_cast<std::size_t>(ct.size()), -1.0);
  for (int64_t i = 0; i < ct.size(); ++i) {
    auto it = std::lower_bound(errors.begin(), errors.end(),
                               std::pair<int64_t, double>{ct.nodes[i], -1.0});
    if (it != errors.end() && it->first == ct.nodes[i])
      slack[i] = it->second;
  }
  StandInContraction c = contract_stand_in_arcs(ct, slack);
  if (c.contracted > 0)
    ct = std::move(c.tree);
  return c.contracted;
}

} // namespace

TreeResult exact_contour_tree(const Mesh &mesh, const ExactTreeOptions &opt) {
  // Large arrays freed by one phase give their pages to the next.
  const PageReuseScope reuse_pages;
  TreeTimings time;
  ExactGraphBuild build = build_exact_graph(mesh, opt, time);
  const EdgeNodes &en = build.edge_nodes;
  ExactGraph &graph = build.graph;
  const DegenerateCells &degenerate = build.degenerate;
  const int threads = build.threads;
  Stopwatch clock;

  // 6. The join and split sweeps, 7. their merge.
  SweepTimings sweep_time;
  const std::vector<uint8_t> keep =
      opt.cut ? seam_nodes(*opt.cut, en, graph.size()) : std::vector<uint8_t>{};
  ContourTree ct = sweep_exact_graph(mesh, en, graph, opt, sweep_time, keep);
  // 8. On a surface cut open, the disks' tree glued back along the seams: the Reeb graph.
  GluedGraph glued;
  PathGluing gluing;
  if (opt.cut) {
    Stopwatch glue_clock;
    gluing = seam_gluing(*opt.cut, en, graph.values, degenerate.lattice_on_edge);
    glued = glue_paths(ct, gluing, !opt.augmented);
    ct = std::move(glued.graph);
    time.gluing = glue_clock.seconds();
  }
  const int64_t contracted = contract_stand_in(degenerate, opt.augmented, ct);
  time.sweeps = sweep_time.order + sweep_time.sweeps;
  time.merge = sweep_time.merge;
  if (opt.progress) {
    opt.progress("join and split sweeps", *time.sweeps);
    opt.progress("merge", *time.merge);
  }
  clock.lap();

  // 9. The result: the tree's nodes in the mesh, and the graph to draw its arcs.
  const std::vector<std::array<int64_t, 2>> links = seam_links(gluing);
  TreeResult r = tree_result(mesh, en, graph, ct, opt.augmented, links);
  offset_values(r, mesh.field.reference());
  if (opt.arc_geometry)
    r.graph = exact_arc_graph(mesh, en, graph, opt, threads, links);
  time.output = clock.lap();

  ExactCounts &n = r.stats.exact.emplace(exact_counts(mesh, build));
  n.fallback_arcs_contracted = contracted;
  if (opt.cut) { // (compute_tree labels the result a Reeb graph, cut or not)
    count_copies_once(*opt.cut, en, n);
    r.loops = graph_loops(ct);
    r.stats.seam_edges = static_cast<int64_t>(opt.cut->seams.size());
    r.stats.seam_paths_nonmonotone = glued.nonmonotone_paths;
  }
  split_cell_time(build.totals, time);
  r.stats.time = time;
  return r;
}

} // namespace hoct
