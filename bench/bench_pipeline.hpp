// One run of what `hoct tree FILE --json OUT [--vtp OUT]` does, timed phase by phase: read the
// file, build the mesh (topology, Lagrange -> Bernstein conversion, checks), the exact tree's
// phases, and the output (flat-region contraction, branch decomposition, JSON and VTP written).
#pragma once

#include "bench_support.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hoct::bench {

struct PipelineResult {
  // input: read, the whole mesh build, and the Lagrange -> Bernstein conversion within it
  double read = 0, mesh = 0, bernstein = 0;
  // exact_contour_tree's phases: edge nodes (the edges' critical points), the cells (their
  // interior critical points, then their certified connections; split by the threads' time in
  // each), graph assembly (gathering, fallback cells, edge chains), sweeps, merge.
  double edges = 0, cell_work = 0, interior = 0, connections = 0, assembly = 0, sweeps = 0,
         merge = 0;
  double tree = 0; // exact_contour_tree as a whole
  // A Reeb graph (a domain with holes or handles): the cut into disks and the gluing, both
  // within `tree`; its loops and the edges cut open.
  double cut = 0, gluing = 0;
  int64_t loops = 0, seam_edges = 0;
  double write = 0; // contraction, branches, files
  double total = 0; // read .. write
  int64_t cells = 0, graph_nodes = 0;
  std::size_t nodes = 0; // tree nodes after the flat-region contraction
  double fallback_cells = 0, constant_cells = 0;

  double cell_phase() const { return edges + cell_work + assembly; }
  double mesh_checks() const { return mesh - bernstein; } // topology, checks, geometry
};

PipelineResult run_pipeline(const std::string &vtu, int threads, bool with_vtp,
                            const ScratchDir &scratch);

// Phase-wise medians of several runs (counts from the first run).
PipelineResult median_of(const std::vector<PipelineResult> &runs);

} // namespace hoct::bench
