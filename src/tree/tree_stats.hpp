// The statistics of a computed tree, typed: what the exact pipeline counted (nodes, connections,
// every fallback by reason), what the PL tree worked on, what the reductions did, and the time
// of each phase. Writers list them as name/value entries (entries()), in one fixed order.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hoct {

// Why a cell of the exact pipeline falls back to the PL rule on a refinement of itself.
enum class FallbackReason : uint8_t {
  ConstantCell,        // the cell's polynomial is constant
  CriticalCurve,       // its gradient vanishes on a curve (the zero search ran out of budget)
  UncertifiedZero,     // a gradient zero the search could not certify
  ZeroNearBoundary,    // a gradient zero too close to the cell's boundary to be placed
  DegenerateEdge,      // one of its edges is constant or has a degenerate critical point
  DegenerateEdgeNode,  // an edge node whose sectors cannot be told apart
  CertificationFailed, // a sector no certified monotone path connects
};
inline constexpr int kFallbackReasons = 7;
// "fallback_constant_cell", ...: the statistic's name.
const char *stat_name(FallbackReason r);

struct ExactCounts {
  int64_t cells = 0;
  int64_t graph_nodes = 0;
  int64_t edge_critical_points = 0;
  // Constant edges across which the field rises or falls (cell/level_edges.hpp): no node, no
  // fallback; counted once per cell side (an inner edge level on both sides counts twice).
  int64_t level_edges = 0;
  int64_t interior_critical_points = 0;
  int64_t connections_direct = 0, connections_traced = 0, connections_failed = 0;
  int64_t descent_steps = 0;
  int64_t fallback_cells = 0;
  std::array<int64_t, kFallbackReasons> fallback_by_reason{}; // cells with each reason
  // The largest certified distance of the fallback cells' PL stand-in from the field, and the
  // arcs of the stand-in within twice it, contracted (tree/stand_in_contraction.hpp).
  double fallback_error = 0;
  int64_t fallback_arcs_contracted = 0;
  int64_t unresolved_interior_zeros = 0;
  // Degenerate critical points (singular Hessian) classified by their sectors
  // (cell/degenerate_points.hpp), regular ones included, and the largest certified bound on how
  // far the field strays from such a node's value within the tiny square it stands for.
  int64_t degenerate_points = 0;
  // Cell corners at a critical vertex (an edge's derivative vanishes there) whose sectors inside
  // the cell were classified (a vertex counts once per cell around it).
  int64_t critical_corners = 0;
  // Curves of critical points (ridges, valleys) classified as one node each with its sectors
  // (cell/critical_curves.hpp), counted once per cell they cross; their slack is part of
  // degenerate_slack.
  int64_t critical_curves = 0;
  double degenerate_slack = 0;

  int64_t fallbacks(FallbackReason r) const { return fallback_by_reason[static_cast<int>(r)]; }
};

struct PlCounts {
  int64_t vertices = 0, triangles = 0;
};

// Seconds per phase; empty where the phase did not run or was not timed.
struct TreeTimings {
  std::optional<double> read, check, bernstein, pl_mesh;
  // Parts of the mesh build (check): quadrilaterals and Bezier cells split into Lagrange
  // triangles, the topology, the cells' geometric maps and their checks.
  std::optional<double> cell_split, topology, geometry, geometry_checks;
  // The exact pipeline's phases.
  std::optional<double> edge_nodes, cells, interior_critical_points, connections, graph_assembly;
  std::optional<double> graph; // the PL tree's graph
  std::optional<double> sweeps, merge, pairs, output;
  // A Reeb graph: the surface cut open into disks, and the disks' tree glued along the seams.
  std::optional<double> cut, gluing;
  std::optional<double> tree; // the whole tree computation
  // After it: flat regions contracted and branches decomposed; the arcs drawn on the surface
  // (only when they are, for a .vtp or ParaView).
  std::optional<double> branches, arc_paths;
};

struct TreeStats {
  std::optional<ExactCounts> exact;
  std::optional<PlCounts> pl;
  std::optional<int64_t> input_cells;
  std::optional<int64_t> flat_nodes_merged;
  std::optional<int64_t> nodes_before_simplification;
  std::optional<double> simplification_threshold;
  std::optional<int64_t> loops_removed; // by a simplification asked to remove loops
  // The smallest persistence the input's values resolve (mesh/field.hpp, Field::precision), and
  // the pairs at or below it: uncertain, kept and flagged.
  std::optional<double> precision;
  std::optional<int64_t> pairs_below_precision;
  // Pairs with a fallback node within twice the stand-in's slack (TreeResult::uncertain).
  std::optional<int64_t> pairs_within_fallback_slack;
  // Pairs within twice the degenerate points' slack (TreeResult::uncertain).
  std::optional<int64_t> pairs_within_degenerate_slack;
  // A Reeb graph's cut (mesh/cut_surface, tree/path_gluing): the edges cut open, and the seam
  // pieces whose paths in the disks' tree do not rise (glued at their ends only).
  std::optional<int64_t> seam_edges, seam_paths_nonmonotone;
  TreeTimings time;
  // Entries this version does not know (read from another version's JSON), kept as they are.
  std::vector<std::pair<std::string, double>> other;

  // As name/value pairs ("cells", ..., "time_tree_s"), in one fixed order; the time_* entries
  // and seam_edges (how the surface was cut: one process's cut differs from the pieces') only
  // with `timings`.
  std::vector<std::pair<std::string, double>> entries(bool timings = true) const;
  // The inverse of entries() (unknown names go to `other`).
  static TreeStats from_entries(const std::vector<std::pair<std::string, double>> &entries);
};

} // namespace hoct
