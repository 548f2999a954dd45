#include "bench_pipeline.hpp"

#include "io/read_mesh.hpp"
#include "io/tree_json.hpp"
#include "io/tree_vtp_writer.hpp"
#include "mesh/mesh.hpp"
#include "tree/exact_contour_tree.hpp"
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
  ExactTreeOptions eo;
  eo.threads = threads;
  eo.arc_geometry = with_vtp;
  auto t = clock_type::now();
  TreeResult tree = exact_contour_tree(mesh, eo);
  r.tree = seconds_since(t);
  r.edges = stat(tree, "time_edge_nodes_s");
  r.cell_work = stat(tree, "time_cells_s");
  r.interior = stat(tree, "time_interior_critical_points_s");
  r.connections = stat(tree, "time_connections_s");
  r.assembly = stat(tree, "time_graph_assembly_s");
  r.sweeps = stat(tree, "time_sweeps_s");
  r.merge = stat(tree, "time_merge_s") + stat(tree, "time_output_s");
  r.graph_nodes = static_cast<int64_t>(stat(tree, "graph_nodes"));
  r.fallback_cells = stat(tree, "fallback_cells");
  r.constant_cells = stat(tree, "fallback_constant_cell");
  r.cells = mesh.topology.num_cells();
  t = clock_type::now();
  tree = contract_flat(tree);
  decompose_branches(tree);
  write_tree_json(scratch.file("tree.json"), tree);
  if (with_vtp) {
    compute_arc_paths(tree, threads);
    write_tree_vtp(scratch.file("tree.vtp"), tree);
  }
  r.write = seconds_since(t);
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
                 &PipelineResult::merge, &PipelineResult::tree, &PipelineResult::write,
                 &PipelineResult::total})
    med(f);
  return m;
}

} // namespace hoct::bench
