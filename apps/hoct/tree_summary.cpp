#include "tree_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

namespace hoct::cli {

std::string graph_kind(const TreeResult &tree) {
  if (!tree.reeb_graph)
    return "tree";
  return "Reeb graph (" + std::to_string(tree.loops) + (tree.loops == 1 ? " loop)" : " loops)");
}

std::string describe_mesh(const std::string &file, const Mesh &mesh) {
  const std::string detail = mesh.field_detail.empty() ? "" : " " + mesh.field_detail;
  const std::string cells = std::to_string(mesh.topology.num_cells());
  const std::string degree = "max degree " + std::to_string(mesh.field.max_degree());
  return file + ": field '" + mesh.field_name + "'" + detail + ", " +
         (mesh.origins.identity()
              ? cells + " cells (" + degree + ")"
              : std::to_string(mesh.num_input_cells()) + " cells (" + mesh.describe_input_cells() +
                    "; as " + cells + " triangles, " + degree + ")");
}

void print_tree_summary(const std::string &mesh_line, const TreeResult &tree,
                        double total_seconds) {
  std::printf("%s, %s %s\n", mesh_line.c_str(), tree.method.c_str(), graph_kind(tree).c_str());
  print_tree_body(tree, total_seconds);
}

void print_tree_body(const TreeResult &tree, double total_seconds) {
  const auto counts = tree.type_counts();
  std::map<std::string, int64_t> loc;
  for (const auto &n : tree.nodes)
    ++loc[to_string(n.location)];
  std::printf("  nodes: %zu (minima %lld, maxima %lld, saddles %lld", tree.nodes.size(),
              static_cast<long long>(counts[0]), static_cast<long long>(counts[1]),
              static_cast<long long>(counts[2]));
  if (tree.augmented)
    std::printf(", regular %lld", static_cast<long long>(counts[3]));
  std::printf("), arcs: %zu", tree.arcs.size());
  if (tree.stats.nodes_before_simplification)
    std::printf(", %lld nodes before simplification",
                static_cast<long long>(*tree.stats.nodes_before_simplification));
  std::printf("\n");
  std::printf("  where:");
  for (const auto &[k, v] : loc)
    std::printf(" %s %lld", k.c_str(), static_cast<long long>(v));
  std::printf("\n");
  std::vector<double> pers;
  for (const auto &p : tree.pairs)
    pers.push_back(p.persistence());
  std::sort(pers.rbegin(), pers.rend());
  std::printf("  persistence pairs: %zu", pers.size());
  if (!pers.empty()) {
    std::printf(" (largest");
    for (std::size_t i = 0; i < std::min<std::size_t>(5, pers.size()); ++i)
      std::printf(" %.6g", pers[i]);
    std::printf(")");
  }
  if (tree.stats.precision)
    std::printf("\n  precision of the data: %.3g (%lld pair(s) at or below it, flagged uncertain)",
                *tree.stats.precision,
                static_cast<long long>(tree.stats.pairs_below_precision.value_or(0)));
  if (tree.stats.exact && tree.stats.exact->fallback_error > 0)
    std::printf("\n  fallback stand-in: within %.3g of the field (%lld arc(s) contracted, %lld "
                "pair(s) within twice that, flagged uncertain)",
                tree.stats.exact->fallback_error,
                static_cast<long long>(tree.stats.exact->fallback_arcs_contracted),
                static_cast<long long>(tree.stats.pairs_within_fallback_slack.value_or(0)));
  if (tree.stats.exact && tree.stats.exact->degenerate_slack > 0)
    std::printf("\n  degenerate critical points: %lld inside cells, %lld cell corner(s) at "
                "critical vertices and %lld critical curve piece(s) classified by their sectors "
                "(each within %.3g of the field on the region it stands for; %lld pair(s) within "
                "twice that, flagged uncertain)",
                static_cast<long long>(tree.stats.exact->degenerate_points),
                static_cast<long long>(tree.stats.exact->critical_corners),
                static_cast<long long>(tree.stats.exact->critical_curves),
                tree.stats.exact->degenerate_slack,
                static_cast<long long>(tree.stats.pairs_within_degenerate_slack.value_or(0)));
  std::printf("\n  stats:");
  int col = 0;
  for (const auto &[k, v] : tree.stats.entries()) {
    std::printf("%s %s=%.6g", col % 4 == 0 ? "\n   " : "", k.c_str(), v);
    ++col;
  }
  std::printf("\n  total %.3f s\n", total_seconds);
}

void print_branches(const TreeResult &t) {
  const auto &b = t.branches;
  const auto children = branch_children(b);
  std::printf("branches: %zu\n", b.size());
  if (b.empty())
    return;
  auto line = [&](int64_t i) {
    const TreeNode &e = t.nodes[b[i].extremum], &s = t.nodes[b[i].saddle];
    std::printf("%*s%s %lld (%.6g) -> %s %lld (%.6g), persistence %.6g\n", 2 + 2 * b[i].depth, "",
                to_string(e.type), static_cast<long long>(b[i].extremum), e.value,
                to_string(s.type), static_cast<long long>(b[i].saddle), s.value, b[i].persistence);
  };
  std::vector<int64_t> stack = {0};
  while (!stack.empty()) {
    const int64_t i = stack.back();
    stack.pop_back();
    line(i);
    for (auto it = children[i].rbegin(); it != children[i].rend(); ++it)
      stack.push_back(*it);
  }
}

} // namespace hoct::cli
