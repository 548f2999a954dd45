// The invariant checker: does a contour tree (however it was computed or read back) agree with
// the mesh and field it claims to describe? It checks
//   - tree-ness: nodes - components arcs, connected per mesh component, acyclic;
//   - the Euler relation: sum over nodes of (degree - 2) = -2 per component;
//   - order: nodes ascending by value, every arc from the lower to the higher node;
//   - positions: each node's value is the field at its (cell, u, v), its position the cell's
//     geometry map there (tolerances relative to the value range and the mesh extent);
//   - types versus degrees: minima have arcs up only, maxima down only (one, or more for a
//     flat region contracted into one node, which the samples then judge), saddles degree >= 3
//     with arcs both ways, regular nodes one arc up and one down;
//   - types versus the field: f - f(node) sampled on small circles around the node, in every
//     cell around it (the fan of a vertex, both cells of an edge), gives the number of lower and
//     upper sectors; a minimum has no lower one, a maximum no upper one, a saddle at least two of
//     one kind, a regular node one of each, and no node has more arcs down (up) than sectors.
//   - pairs: the recorded persistence pairs are the elder-rule pairs of the tree's arcs, and a
//     persistence a file recorded is its nodes' difference;
//   - completeness: every strict local extremum at a vertex or on an edge that the edge
//     polynomials decide (every edge ascending from a vertex; an edge's critical point rising
//     into every cell of the edge) is a minimum (maximum) node of the tree.
// Nodes of degenerate (fallback) cells, nodes standing for a flat region (TreeNode::merged > 1)
// and nodes whose neighbourhood is flat to rounding are reported as skipped, not as failures.
// No I/O.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hoct {

struct TreeFinding {
  // "tree", "loops", "euler", "order", "value", "position", "degree", "type", "pairs",
  // "completeness"
  std::string check;
  std::vector<int64_t> nodes; // indices into TreeResult::nodes
  std::vector<int64_t> arcs;  // indices into TreeResult::arcs
  std::string message;
};

struct TreeCheckReport {
  std::vector<TreeFinding> failures;
  std::vector<TreeFinding> skipped; // checks that could not be decided (fallback, flat, ...)
  int64_t nodes_checked = 0;        // nodes whose type was confirmed by the samples
  int64_t extrema_confirmed = 0;    // extrema decided from the edge polynomials, found in the tree
  bool ok() const { return failures.empty(); }
  // One line per failure (and a count of skipped nodes).
  std::string summary(std::size_t max_lines = 20) const;
};

struct TreeCheckOptions {
  // |value - field(cell, u, v)| allowed, relative to max(value range, largest |value|).
  double value_tolerance = 1e-9;
  // |position - geometry(cell, u, v)| allowed, relative to the mesh extent.
  double position_tolerance = 1e-9;
  // Compare node types with samples of the field around each node.
  bool check_types = true;
  // Samples per cell around a node (per full turn for interior nodes).
  int samples = 64;
  // Look for extrema the tree must have (at vertices and on edges, decided from the edge
  // polynomials) and missing ones.
  bool check_completeness = true;
};

TreeCheckReport check_tree(const TreeResult &tree, const Mesh &mesh,
                           const TreeCheckOptions &options = {});

} // namespace hoct
