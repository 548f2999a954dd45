// What the exact pipeline can be asked (exact_contour_tree).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace hoct {

struct CutSurface;

struct ExactTreeOptions {
  bool augmented = false;
  // Sub-triangles per edge in the degenerate-cell fallback (0: 2 * degree, at least 4).
  int fallback_refinement = 0;
  // Threads for the cell phase (0: all hardware threads). The result does not depend on it.
  int threads = 1;
  // Fewest cells per thread (fewer threads on small meshes, where waking one costs more than it
  // saves); edges use twice as many, the gathering loops 128 times as many. The workers are kept
  // between calls (util/worker_pool), so a few hundred cells already pay.
  int64_t cells_per_thread = 256;
  // Keep the graph with the geometry of every connection (certified paths, edge pieces), so
  // that arcs can be drawn on the surface (compute_arc_paths). Costs memory; off by default.
  bool arc_geometry = false;
  // The mesh is this surface cut open into disks (mesh/cut_surface): the tree of the disks is
  // glued back along the cut's seams into the surface's Reeb graph (exact/seam_gluing).
  const CutSurface *cut = nullptr;
  // Called after each phase with its name and duration (seconds), e.g. for progress output.
  std::function<void(const std::string &, double)> progress;
};

} // namespace hoct
