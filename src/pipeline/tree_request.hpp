// What a front end asks of the library for a tree (TreeRequest), and what it gets back
// (TreeOutcome): the one call between them is compute_tree (pipeline/compute_tree.hpp).
#pragma once

#include "pipeline/threshold.hpp"
#include "tree/tree_result.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hoct {

enum class TreeMethod {
  Exact,  // the exact tree of the piecewise-polynomial field
  Linear, // the PL tree of the input's Lagrange nodes (each cell split through them)
  Refine, // the PL tree of the exact field on K x K sub-triangles per cell
};

// Whether the arcs are to be drawn on the surface (the tree's geometric graph).
enum class ArcGeometry {
  None,     // arcs are straight segments between their nodes
  Graph,    // keep the graph, to draw arcs later (compute_arc_paths)
  Paths,    // draw the reported tree's now (TreeResult::arc_paths)
  AllPaths, // draw those of the tree and of the simplified tree
};

struct TreeRequest {
  TreeMethod method = TreeMethod::Exact;
  int refine = 4;         // K for TreeMethod::Refine (1-1024)
  bool augmented = false; // keep the regular nodes (then no contraction, no simplification)
  bool keep_flat = false; // keep the nodes and zero-length arcs of plateaus
  std::optional<Threshold> simplify;
  bool simplify_loops = false; // the simplification removes a Reeb graph's loops below it too
  bool force = false; // compute what is well defined on a domain that is not a disk or sphere
  int threads = 0;    // 0: every hardware thread; the result does not depend on it
  ArcGeometry arcs = ArcGeometry::None;
  // Sub-triangles per edge of a degenerate cell's fallback (0: 2 x degree, at least 4).
  int fallback_refinement = 0;
  // How long reading the input and building the mesh took, if the caller timed them (reported
  // as time_read_s and time_check_s).
  std::optional<double> read_seconds, build_seconds;
  // Called after each phase with its name and seconds (progress output of long runs).
  std::function<void(const std::string &, double)> progress;
};

struct TreeOutcome {
  // The tree: reduced trees have each flat region contracted to one node (unless keep_flat)
  // and their branch decomposition; the statistics include the mesh build's.
  TreeResult tree;
  // The tree simplified by request.simplify (its arcs drawn too with ArcGeometry::Paths).
  std::optional<TreeResult> simplified;
  // Why the result is forced (also in tree.forced): say them to the user as warnings.
  std::vector<std::string> warnings;

  // What to report: the simplified tree if there is one, else the tree.
  const TreeResult &reported() const { return simplified ? *simplified : tree; }
};

} // namespace hoct
