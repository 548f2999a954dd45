// What hoct reports for a contour tree, independent of how it was computed (exact, PL of the
// input's nodes, PL of a refinement) and of the output format: nodes with type, value, position
// and where they sit in the input mesh; arcs; persistence pairs; and typed statistics (counts,
// timings, fallbacks: tree/tree_stats.hpp). Writers (io/tree_json, io/tree_vtp_writer) consume it.
#pragma once

#include "tree/contour_tree.hpp"
#include "tree/geometric_graph.hpp"
#include "tree/persistence.hpp"
#include "tree/simplification.hpp"
#include "tree/tree_stats.hpp"
#include "util/fingerprint.hpp"
#include "util/stopwatch.hpp"
#include "util/vec.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hoct {

enum class NodeLocation : uint8_t { Vertex, Edge, Interior, Unknown };
const char *to_string(NodeLocation l);

struct TreeNode {
  NodeType type = NodeType::Regular;
  double value = 0;
  Vec3 position{0, 0, 0};
  int64_t cell = -1;              // a cell of the input mesh containing the node
  std::array<double, 2> uv{0, 0}; // its parametric position in that cell
  NodeLocation location = NodeLocation::Unknown;
  int32_t up = 0, down = 0; // arcs to higher / lower nodes
  // The node lies in (or on the boundary of) a degenerate cell that fell back to the PL rule:
  // its value is exact, its type is that of the refinement.
  bool fallback = false;
  int64_t graph_node = -1; // the node of TreeResult::graph it stands for (if any)
  // The number of nodes of a flat region (equal values) contract_flat merged into this one: the
  // node then stands for all of them, and sits at one of their positions.
  int64_t merged = 1;
};

struct TreeResult {
  std::string method; // "exact", "linear", "refine k=4", ...
  bool augmented = false;
  std::vector<TreeNode> nodes;              // ascending in the total order (value, id)
  std::vector<std::array<int64_t, 2>> arcs; // indices into nodes, lower node first
  std::vector<PersistencePair> pairs;       // birth/death are indices into nodes
  // The persistence of each pair as a file recorded it (read_tree_json), for the checker to
  // compare with its nodes' values; empty for a computed tree.
  std::vector<double> recorded_persistence;
  std::vector<Branch> branches; // branch decomposition (indices into nodes)
  // A Reeb graph: the domain is not a disk or a sphere (holes, handles, several components), so
  // the level sets may form loops; `loops` is the graph's first Betti number (arcs - nodes +
  // components; parallel arcs between two nodes are a loop). A contour tree has none.
  bool reeb_graph = false;
  int64_t loops = 0;
  TreeStats stats;
  // Why the result was computed although the input is not a valid disk or sphere (hoct tree
  // --force); empty for a regular result.
  std::vector<std::string> forced;
  // The input the tree was computed from (sizes, field, fingerprint: util/fingerprint.hpp), for
  // a consumer of the tree to check it is given that mesh; unset when unknown (a tree file
  // written before hoct recorded it, a tree computed outside compute_tree).
  std::optional<InputFingerprint> input;
  // The graph the tree came from, with geometry (optional), and each arc drawn on the surface
  // (compute_arc_paths; empty = straight arcs).
  std::shared_ptr<const GeometricGraph> graph;
  std::vector<std::vector<Vec3>> arc_paths;

  // A pair at or below the input's precision (stats.precision): its existence and persistence
  // are not resolved by the data.
  bool below_precision(const PersistencePair &p) const {
    return stats.precision && p.persistence() <= *stats.precision;
  }
  // A pair with a node of a fallback cell's PL stand-in and a persistence within twice the
  // stand-in's certified slack (ExactCounts::fallback_error): not resolved by the stand-in.
  bool within_fallback_slack(const PersistencePair &p) const {
    if (!stats.exact || !(stats.exact->fallback_error > 0) ||
        !(p.persistence() <= 2 * stats.exact->fallback_error))
      return false;
    auto fallback = [&](int64_t i) {
      return i >= 0 && i < static_cast<int64_t>(nodes.size()) && nodes[i].fallback;
    };
    return fallback(p.birth) || fallback(p.death);
  }
  // A pair within twice the degenerate critical points' slack (ExactCounts::degenerate_slack):
  // such a node stands for a square of about 1e-6 of its cell, inside which structure that small
  // is not resolved (a conservative flag: any pair that small).
  bool within_degenerate_slack(const PersistencePair &p) const {
    return stats.exact && stats.exact->degenerate_slack > 0 &&
           p.persistence() <= 2 * stats.exact->degenerate_slack;
  }
  // Any of these: the pair is flagged "uncertain" in the outputs.
  bool uncertain(const PersistencePair &p) const {
    return below_precision(p) || within_fallback_slack(p) || within_degenerate_slack(p);
  }

  // Counts of nodes by type: minimum, maximum, saddle, regular.
  std::array<int64_t, 4> type_counts() const;
};

// Persistence pairs of a (reduced or augmented) contour tree, with node indices of the tree
// (the join and split sweeps on a thread each with `threads` >= 2; the same pairs).
std::vector<PersistencePair> tree_pairs(const ContourTree &tree, int threads = 1);

// The result for contour tree `ct` of a graph, computed by `method`: each node's type, value,
// degrees and graph node (its id in `ct`), the arcs and the persistence pairs; `place(node)`
// then says where each node lies (position, cell, uv, location, fallback). With
// `pairs_seconds`, the time the persistence pairs took is stored there; `threads` for them.
template <class Place>
TreeResult tree_result_of(const ContourTree &ct, const std::string &method, bool augmented,
                          Place &&place, double *pairs_seconds = nullptr, int threads = 1) {
  TreeResult r;
  r.method = method;
  r.augmented = augmented;
  const auto types = ct.types();
  const auto deg = ct.degrees();
  r.nodes.resize(static_cast<std::size_t>(ct.size()));
  for (int64_t i = 0; i < ct.size(); ++i) {
    TreeNode &n = r.nodes[i];
    n.type = types[i];
    n.value = ct.values[i];
    n.graph_node = ct.nodes[i];
    n.up = deg[i][0];
    n.down = deg[i][1];
    place(n);
  }
  r.arcs = ct.arcs;
  const Stopwatch clock;
  r.pairs = tree_pairs(ct, threads);
  if (pairs_seconds)
    *pairs_seconds = clock.seconds();
  return r;
}

// Adds `reference` to the values of the nodes and pairs: a tree computed from values relative
// to a reference (mesh/field.hpp) reports absolute ones. The order stays (rounding is
// monotone); persistence is then as precise as the absolute values.
void offset_values(TreeResult &tree, double reference);

// Records the input's precision in the statistics and counts the pairs at or below it, and
// those within the fallback stand-in's slack.
void set_precision(TreeResult &tree, double precision);

// The tree as a ContourTree (indices of `nodes` as node ids).
ContourTree as_contour_tree(const TreeResult &tree);

// Simplifies a reduced tree by persistence (absolute threshold): keeps the nodes that survive,
// recomputes pairs and branches, and records "nodes_before_simplification" and
// "simplification_threshold" in the statistics. With `loops`, a Reeb graph's loops below the
// threshold go too ("loops_removed").
TreeResult simplify_tree(const TreeResult &tree, double threshold, bool loops = false);

// Contracts the zero-length arcs (within 1e-12 of the value range, plus the rounding of
// values of the nodes' magnitude) of flat regions
// (tree/flat_regions.hpp), recomputes pairs and
// branches, and records "flat_nodes_merged" in the statistics.
TreeResult contract_flat(const TreeResult &tree);
// The same, consuming `tree`: where nothing is contracted, its nodes and pairs are moved, not
// copied.
TreeResult contract_flat(TreeResult &&tree);

// Draws every arc on the surface through the tree's graph (needs tree.graph), the arcs on
// `threads` threads (0 = all hardware threads); the same paths for any number.
void compute_arc_paths(TreeResult &tree, int threads = 1);

// Fills tree.branches with the branch decomposition of the (reduced) tree.
void decompose_branches(TreeResult &tree);

// Parametric location class of (u, v) in the reference triangle (tolerance 1e-12).
NodeLocation classify_location(double u, double v);

} // namespace hoct
