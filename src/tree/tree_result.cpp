#include "tree/tree_result.hpp"

#include "tree/loop_pairs.hpp"

#include "tree/flat_regions.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace hoct {

const char *to_string(NodeLocation l) {
  switch (l) {
  case NodeLocation::Vertex:
    return "vertex";
  case NodeLocation::Edge:
    return "edge";
  case NodeLocation::Interior:
    return "interior";
  case NodeLocation::Unknown:
    return "unknown";
  }
  return "?";
}

std::array<int64_t, 4> TreeResult::type_counts() const {
  std::array<int64_t, 4> c{0, 0, 0, 0};
  for (const auto &n : nodes)
    ++c[static_cast<int>(n.type)];
  return c;
}

std::vector<PersistencePair> tree_pairs(const ContourTree &tree, int threads) {
  // Nodes ascending in the total order (as every tree and graph here has them): no sort.
  if (std::is_sorted(tree.values.begin(), tree.values.end())) {
    std::vector<PersistencePair> pairs =
        persistence_diagram_ascending(tree.values, tree.arcs, threads).pairs;
    for (const PersistencePair &p : loop_pairs(tree))
      pairs.push_back(p);
    return pairs;
  }
  std::vector<GraphEdge> edges;
  edges.reserve(tree.arcs.size());
  for (const auto &a : tree.arcs)
    edges.push_back({a[0], a[1]});
  // Tree nodes are ascending in the total order, so their indices keep its tie-breaking.
  const ScalarGraph g(tree.values, edges);
  std::vector<PersistencePair> pairs = persistence_diagram(g).pairs;
  // A Reeb graph's loops: one essential pair each.
  for (const PersistencePair &p : loop_pairs(tree))
    pairs.push_back(p);
  return pairs;
}

ContourTree as_contour_tree(const TreeResult &t) {
  ContourTree ct;
  ct.nodes.reserve(t.nodes.size());
  ct.values.reserve(t.nodes.size());
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    ct.nodes.push_back(static_cast<int64_t>(i));
    ct.values.push_back(t.nodes[i].value);
  }
  ct.arcs = t.arcs;
  return ct;
}

void decompose_branches(TreeResult &t) {
  if (t.augmented || t.nodes.size() < 2) {
    t.branches.clear();
    return;
  }
  std::vector<double> values(t.nodes.size());
  for (std::size_t i = 0; i < t.nodes.size(); ++i)
    values[i] = t.nodes[i].value;
  t.branches = branch_decomposition(values, t.arcs);
}

namespace {

// The result for a tree derived from t's (contracted or simplified): `kept[i]` is the node of t
// that node i of `tree` stands for; types and degrees follow the new tree. With `take` (t itself,
// which may be consumed) and nothing changed, t's nodes and pairs are moved.
TreeResult derived_result(const TreeResult &t, const ContourTree &tree,
                          const std::vector<int64_t> &kept, TreeResult *take = nullptr) {
  TreeResult r;
  r.method = t.method;
  r.augmented = false;
  const auto deg = tree.degrees();
  const auto types = tree.types();
  // Nothing changed (no flat region on a noisy field, say): t's pairs are the tree's.
  bool same = kept.size() == t.nodes.size() && tree.arcs == t.arcs;
  for (std::size_t i = 0; same && i < kept.size(); ++i)
    same = kept[i] == static_cast<int64_t>(i);
  if (same && take) {
    r.nodes = std::move(take->nodes);
    r.pairs = std::move(take->pairs);
  } else {
    r.nodes.reserve(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i)
      r.nodes.push_back(t.nodes[kept[i]]);
    r.pairs = same ? t.pairs : tree_pairs(tree);
  }
  for (std::size_t i = 0; i < kept.size(); ++i) {
    TreeNode &n = r.nodes[i];
    n.up = deg[i][0];
    n.down = deg[i][1];
    n.type = types[i];
  }
  r.arcs = tree.arcs;
  r.reeb_graph = t.reeb_graph;
  r.loops = graph_loops(tree);
  r.stats = t.stats;
  r.input = t.input;
  r.graph = t.graph;
  return r;
}

TreeResult contract_flat(const TreeResult &t, TreeResult *take) {
  // Flat up to the rounding of polynomial evaluation, relative to the range (values are
  // computed relative to a reference near them), plus two units in the last place of the
  // absolute values they were shifted back to.
  double magnitude = 0;
  for (const auto &n : t.nodes)
    magnitude = std::max(magnitude, std::abs(n.value));
  const double range = t.nodes.empty() ? 0 : t.nodes.back().value - t.nodes.front().value;
  const double tolerance = 1e-12 * range + 2 * std::numeric_limits<double>::epsilon() * magnitude;
  const FlatContraction f = contract_flat_arcs(as_contour_tree(t), tolerance);
  const std::size_t before = t.nodes.size();
  TreeResult r = derived_result(t, f.tree, f.kept, take);
  for (std::size_t i = 0; i < r.nodes.size(); ++i)
    r.nodes[i].merged = f.size[i];
  r.stats.flat_nodes_merged = static_cast<int64_t>(before - r.nodes.size());
  decompose_branches(r);
  return r;
}

} // namespace

void offset_values(TreeResult &t, double reference) {
  if (reference == 0)
    return;
  for (auto &n : t.nodes)
    n.value += reference;
  for (auto &p : t.pairs) {
    p.birth_value += reference;
    p.death_value += reference;
  }
}

void set_precision(TreeResult &t, double precision) {
  t.stats.precision = precision;
  int64_t below = 0, slack = 0, degenerate = 0;
  for (const auto &p : t.pairs) {
    below += t.below_precision(p);
    slack += t.within_fallback_slack(p);
    degenerate += t.within_degenerate_slack(p);
  }
  t.stats.pairs_below_precision = below;
  if (t.stats.exact && t.stats.exact->fallback_error > 0)
    t.stats.pairs_within_fallback_slack = slack;
  if (t.stats.exact && t.stats.exact->degenerate_slack > 0)
    t.stats.pairs_within_degenerate_slack = degenerate;
}

TreeResult contract_flat(const TreeResult &t) { return contract_flat(t, nullptr); }

TreeResult contract_flat(TreeResult &&t) { return contract_flat(t, &t); }

TreeResult simplify_tree(const TreeResult &t, double threshold, bool loops) {
  const Simplification s = simplify(as_contour_tree(t), threshold, loops);
  TreeResult r = derived_result(t, s.tree, s.kept);
  r.stats.nodes_before_simplification = static_cast<int64_t>(t.nodes.size());
  r.stats.simplification_threshold = threshold;
  if (loops)
    r.stats.loops_removed = s.removed_loops;
  decompose_branches(r);
  return r;
}

void compute_arc_paths(TreeResult &t, int threads) {
  t.arc_paths.clear();
  if (!t.graph)
    return;
  // Each arc's path on its own (the same for any thread count), a search scratch per thread.
  // Parallel arcs (a Reeb graph's loops) are drawn after the others, one after the other, each
  // avoiding the nodes of the paths drawn for its siblings: the sides of a hole or a handle.
  const int64_t n = static_cast<int64_t>(t.arcs.size());
  t.arc_paths.resize(t.arcs.size());
  std::vector<int64_t> by_ends(t.arcs.size());
  std::iota(by_ends.begin(), by_ends.end(), int64_t{0});
  std::stable_sort(by_ends.begin(), by_ends.end(),
                   [&](int64_t x, int64_t y) { return t.arcs[x] < t.arcs[y]; });
  std::vector<uint8_t> parallel(t.arcs.size(), 0);
  for (int64_t k = 1; k < n; ++k)
    if (t.arcs[by_ends[k]] == t.arcs[by_ends[k - 1]])
      parallel[by_ends[k]] = parallel[by_ends[k - 1]] = 1;
  // A search below the arc visits at most a given number of nodes before the forests' paths
  // take over (GeometricGraph::beyond_path). First every arc with a short search (`near`, no
  // forest); then
  // the arcs it did not draw with searches that together visit about as many nodes as building
  // the forests costs: a few such arcs get the short paths of a search, the many of a noisy
  // field the forests' paths, without searching much of the surface for each (and the choice
  // depends on no thread's timing).
  constexpr int64_t near = 1024;
  const GeometricGraph &g = *t.graph;
  // Arc i by `how` (a GeometricGraph path between its nodes' graph nodes); straight where a node
  // has none.
  auto draw = [&](int64_t i, GeometricGraph::Search &search, const auto &how) {
    const auto &a = t.arcs[i];
    const int64_t x = t.nodes[a[0]].graph_node, y = t.nodes[a[1]].graph_node;
    t.arc_paths[i] = x < 0 || y < 0
                         ? std::vector<Vec3>{t.nodes[a[0]].position, t.nodes[a[1]].position}
                         : how(i, x, y, search);
  };
  const int used = threads_for(n, thread_count(threads), 16);
  std::vector<GeometricGraph::Search> scratch(static_cast<std::size_t>(used));
  // The arcs with which[i] set, on the threads.
  auto draw_all = [&](const std::vector<uint8_t> &which, const auto &how) {
    parallel_chunks(n, std::min<int64_t>(n, int64_t{used} * 256), used,
                    [&](int64_t, int64_t begin, int64_t end, int worker) {
                      for (int64_t i = begin; i < end; ++i)
                        if (which[i])
                          draw(i, scratch[static_cast<std::size_t>(worker)], how);
                    });
  };
  std::vector<uint8_t> single(t.arcs.size()), undrawn(t.arcs.size(), 0);
  for (int64_t i = 0; i < n; ++i)
    single[i] = !parallel[i];
  draw_all(single, [&](int64_t i, int64_t x, int64_t y, GeometricGraph::Search &search) {
    std::vector<Vec3> p = g.near_path(x, y, search, near);
    undrawn[i] = search.nodes.empty();
    return p;
  });
  // The second pass does not repeat the first's search within the values. (No search below
  // where it would visit no more nodes than the first.)
  const int64_t left = std::count(undrawn.begin(), undrawn.end(), uint8_t{1});
  const int64_t budget = left > 0 ? g.size() / left : 0,
                below = budget <= near ? 0 : std::min(budget, GeometricGraph::kMaxVisits);
  if (left > 0)
    draw_all(undrawn, [&](int64_t, int64_t x, int64_t y, GeometricGraph::Search &search) {
      return g.beyond_path(x, y, search, below);
    });
  // Parallel arcs one after the other, each avoiding its siblings' paths.
  GeometricGraph::Search &search = scratch.front();
  auto full = [&](int64_t, int64_t x, int64_t y, GeometricGraph::Search &s) {
    return g.path(x, y, s);
  };
  for (int64_t k = 0; k < n; ++k) {
    const int64_t i = by_ends[k];
    if (!parallel[i])
      continue;
    if (k == 0 || t.arcs[i] != t.arcs[by_ends[k - 1]])
      search.avoid.assign(static_cast<std::size_t>(g.size()), 0);
    draw(i, search, full);
    for (int64_t v : search.nodes)
      search.avoid[v] = 1;
  }
  search.avoid.clear();
}

NodeLocation classify_location(double u, double v) {
  constexpr double eps = 1e-12;
  const bool on0 = std::abs(v) <= eps, on1 = std::abs(1 - u - v) <= eps, on2 = std::abs(u) <= eps;
  const int count = on0 + on1 + on2;
  if (count >= 2)
    return NodeLocation::Vertex;
  if (count == 1)
    return NodeLocation::Edge;
  return NodeLocation::Interior;
}

} // namespace hoct
