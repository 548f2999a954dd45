#include "tree/simplification.hpp"

#include "tree/leaf_pruning.hpp"
#include "tree/loop_removal.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {

Simplification simplify(const ContourTree &tree, double threshold, bool loops) {
  // Loops below the threshold out first; `base` maps the graph left's nodes to the input's.
  const bool removing = loops && graph_loops(tree) > 0;
  LoopRemoval removal;
  if (removing)
    removal = remove_loops(tree, threshold);
  const ContourTree &in = removing ? removal.graph : tree;
  auto base = [&](int64_t v) { return removing ? removal.kept[static_cast<std::size_t>(v)] : v; };
  LeafPruning pruning(in.values, in.arcs);
  pruning.prune(threshold);
  // The simplified tree: the nodes left, the arcs between them.
  Simplification out;
  const int64_t n = in.size();
  std::vector<int64_t> index(n, -1);
  for (int64_t v = 0; v < n; ++v)
    if (!pruning.removed(v)) {
      index[v] = out.tree.size();
      out.tree.nodes.push_back(in.nodes[v]);
      out.tree.values.push_back(in.values[v]);
      out.kept.push_back(base(v));
    }
  for (const auto &[id, lo, hi] : pruning.arcs_left())
    out.tree.arcs.push_back({index[lo], index[hi]});
  std::sort(out.tree.arcs.begin(), out.tree.arcs.end());
  out.pruned_leaves = static_cast<int64_t>(pruning.order().size());
  out.removed_loops = removal.removed;
  pruning.prune(INFINITY);
  out.branches = pruning.branches();
  for (Branch &b : out.branches) {
    b.extremum = base(b.extremum);
    b.saddle = base(b.saddle);
  }
  return out;
}

std::vector<Branch> branch_decomposition(std::span<const double> values,
                                         std::span<const std::array<int64_t, 2>> arcs) {
  LeafPruning pruning(values, arcs);
  pruning.prune(INFINITY);
  return pruning.branches();
}

std::vector<std::vector<int64_t>> branch_children(const std::vector<Branch> &b) {
  std::vector<std::vector<int64_t>> children(b.size());
  for (std::size_t i = 1; i < b.size(); ++i)
    children[b[i].parent].push_back(static_cast<int64_t>(i));
  for (auto &c : children)
    std::sort(c.begin(), c.end(),
              [&](int64_t x, int64_t y) { return b[x].persistence > b[y].persistence; });
  return children;
}

} // namespace hoct
