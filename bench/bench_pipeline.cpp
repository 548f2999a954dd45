#include "bench_pipeline.hpp"

#include "io/read_mesh.hpp"
#include "io/tree_json.hpp"
#include "io/tree_vtp_writer.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"
#include "util/page_pool.hpp"

#include <algorithm>
#include <utility>

namespace hoct::bench {

PipelineResult run_pipeline(const std::string &vtu, int threads, bool with_vtp,
                            const ScratchDir &scratch) {
  PipelineResult r;
  // As `hoct tree` runs: one page-reuse scope from reading to writing.
  const PageReuseScope reuse_pages;
  const auto t0 = clock_type::now();
  Mesh mesh;
  {
    auto t = clock_type::now();
    // As `hoct tree --threads N` reads it (large raw arrays in parts on its threads).
    ReadLimits limits;
    limits.threads = threads;
    MeshInput input = read_mesh(vtu, "", limits);
    r.read = seconds_since(t);
    t = clock_type::now();
    // As `hoct tree --threads N` builds it: consuming the input (its arrays freed in the build).
    mesh = build_mesh(std::move(input), {.threads = threads});
    r.mesh = seconds_since(t);
    r.bernstein = mesh.build_times.field;
  }
  // As `hoct tree FILE --json T.json [--vtp T.vtp]` asks for it.
  TreeRequest rq;
  rq.threads = threads;
  rq.arcs = with_vtp ? ArcGeometry::Paths : ArcGeometry::None;
  auto t = clock_type::now();
  const TreeOutcome out = compute_tree(mesh, rq);
  const double computed = seconds_since(t);
  const TreeResult &tree = out.tree;
  const TreeTimings &time = tree.stats.time;
  const ExactCounts &n = *tree.stats.exact;
  r.tree = time.tree.value_or(0); // the exact tree itself
  r.edges = time.edge_nodes.value_or(0);
  r.cell_work = time.cells.value_or(0);
  r.interior = time.interior_critical_points.value_or(0);
  r.connections = time.connections.value_or(0);
  r.assembly = time.graph_assembly.value_or(0);
  r.sweeps = time.sweeps.value_or(0);
  r.merge = time.merge.value_or(0) + time.output.value_or(0);
  r.cut = time.cut.value_or(0);
  r.gluing = time.gluing.value_or(0);
  r.loops = tree.loops;
  r.seam_edges = tree.stats.seam_edges.value_or(0);
  r.graph_nodes = n.graph_nodes;
  r.fallback_cells = static_cast<double>(n.fallback_cells);
  r.constant_cells = static_cast<double>(n.fallbacks(FallbackReason::ConstantCell));
  r.cells = mesh.topology.num_cells();
  // Writing: the flat regions' contraction, the branches and the arcs' paths (in compute_tree
  // after the tree), then the files.
  t = clock_type::now();
  write_tree_json(scratch.file("tree.json"), tree);
  if (with_vtp)
    write_tree_vtp(scratch.file("tree.vtp"), tree);
  r.write = computed - r.tree + seconds_since(t);
  r.total = seconds_since(t0);
  r.nodes = tree.nodes.size();
  return r;
}

PipelineResult median_of(const std::vector<PipelineResult> &runs) {
  PipelineResult m = runs.front();
  auto med = [&](double PipelineResult::*field) {
    std::vector<double> v;
    for (const auto &r : runs)
      v.push_back(r.*field);
    m.*field = median(std::move(v));
  };
  for (auto f : {&PipelineResult::read, &PipelineResult::mesh, &PipelineResult::bernstein,
                 &PipelineResult::edges, &PipelineResult::cell_work, &PipelineResult::interior,
                 &PipelineResult::connections, &PipelineResult::assembly, &PipelineResult::sweeps,
                 &PipelineResult::merge, &PipelineResult::tree, &PipelineResult::cut,
                 &PipelineResult::gluing, &PipelineResult::write, &PipelineResult::total})
    med(f);
  return m;
}

} // namespace hoct::bench
