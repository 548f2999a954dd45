// The exact contour tree of a piecewise-polynomial field (the thesis' chapter 3, with the
// certified connections of DESIGN.md): nodes are the mesh vertices, the critical points of every
// edge and of every cell's interior; local connections are the edge chains and certified
// monotone paths from every sector inside a cell; degenerate cells fall back to a refinement
// through their edge nodes with the PL rule; the join and split graphs are swept once, globally,
// and merged. Every fallback is counted in the statistics.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace hoct {

struct ExactTreeOptions {
  bool augmented = false;
  // Sub-triangles per edge in the degenerate-cell fallback (0: 2 * degree, at least 4).
  int fallback_refinement = 0;
  // Threads for the cell phase (0: all hardware threads). The result does not depend on it.
  int threads = 1;
  // Fewest cells per thread (fewer threads on small meshes, where waking one costs more than it
  // saves); edges use twice as many. The workers are kept between calls (util/worker_pool), so
  // a few hundred cells already pay: 2 threads take the 980-cell sphere's tree from ~2.0 to
  // ~1.3-1.5 ms, where 1024 kept it on one.
  int64_t cells_per_thread = 256;
  // Keep the graph with the geometry of every connection (certified paths, edge pieces), so
  // that arcs can be drawn on the surface (compute_arc_paths). Costs memory; off by default.
  bool arc_geometry = false;
  // Called after each phase with its name and duration (seconds), e.g. for progress output.
  std::function<void(const std::string &, double)> progress;
};

TreeResult exact_contour_tree(const Mesh &mesh, const ExactTreeOptions &options = {});

} // namespace hoct
