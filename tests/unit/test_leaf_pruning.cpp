// Leaf pruning (simplify, branch_decomposition) against a quadratic reference that follows the
// rules literally: at each step every current leaf is looked at, and the least (persistence,
// leaf, saddle) of those that may go is pruned; arcs carry the nodes spliced into them, and a
// branch's parent is the branch whose arc holds its saddle. Random trees with few distinct
// values (ties everywhere), unreduced trees, forests and graphs with loops and parallel arcs.
#include "tree/contour_tree.hpp"
#include "tree/simplification.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <tuple>

namespace hoct {
namespace {

struct Reference {
  std::vector<Branch> branches;
  Simplification simplified; // without its branches
};

Reference reference_pruning(const ContourTree &t, double threshold) {
  const int64_t n = t.size();
  struct Arc {
    int64_t lo, hi;
    bool alive;
    std::vector<int64_t> inside; // nodes spliced into it
  };
  std::vector<Arc> arcs;
  for (const auto &a : t.arcs)
    arcs.push_back({a[0], a[1], true, {}});
  std::vector<char> removed(n, 0);
  struct Pruned {
    int64_t leaf, saddle, arc;
    double persistence;
  };
  std::vector<Pruned> order;
  Reference out;
  auto prune = [&](double limit) {
    while (true) {
      // Arcs up and down at each node.
      std::vector<std::vector<int64_t>> up(n), down(n);
      for (std::size_t k = 0; k < arcs.size(); ++k)
        if (arcs[k].alive) {
          up[arcs[k].lo].push_back(static_cast<int64_t>(k));
          down[arcs[k].hi].push_back(static_cast<int64_t>(k));
        }
      int64_t alive = 0;
      for (int64_t v = 0; v < n; ++v)
        alive += !removed[v];
      if (alive <= 2)
        return;
      bool found = false;
      std::tuple<double, int64_t, int64_t> best;
      int64_t best_arc = -1;
      for (int64_t v = 0; v < n; ++v) {
        if (removed[v] || up[v].size() + down[v].size() != 1)
          continue;
        const bool is_min = up[v].size() == 1;
        const int64_t k = is_min ? up[v][0] : down[v][0];
        const int64_t s = is_min ? arcs[k].hi : arcs[k].lo;
        // The saddle keeps an arc on the leaf's side.
        if ((is_min ? down[s].size() : up[s].size()) < 2)
          continue;
        const auto key = std::make_tuple(std::abs(t.values[v] - t.values[s]), v, s);
        if (!found || key < best) {
          found = true;
          best = key;
          best_arc = k;
        }
      }
      if (!found || !(std::get<0>(best) < limit))
        return;
      const auto [pers, leaf, s] = best;
      order.push_back({leaf, s, best_arc, pers});
      arcs[best_arc].alive = false;
      removed[leaf] = 1;
      // A saddle left with one arc up and one down is spliced out.
      std::vector<int64_t> below, above;
      for (std::size_t k = 0; k < arcs.size(); ++k)
        if (arcs[k].alive && arcs[k].hi == s)
          below.push_back(static_cast<int64_t>(k));
        else if (arcs[k].alive && arcs[k].lo == s)
          above.push_back(static_cast<int64_t>(k));
      if (below.size() == 1 && above.size() == 1) {
        Arc merged{arcs[below[0]].lo, arcs[above[0]].hi, true, arcs[below[0]].inside};
        merged.inside.push_back(s);
        for (int64_t x : arcs[above[0]].inside)
          merged.inside.push_back(x);
        arcs[below[0]].alive = arcs[above[0]].alive = false;
        removed[s] = 1;
        arcs.push_back(merged);
      }
    }
  };
  prune(threshold);
  std::vector<int64_t> index(n, -1);
  for (int64_t v = 0; v < n; ++v)
    if (!removed[v]) {
      index[v] = out.simplified.tree.size();
      out.simplified.tree.nodes.push_back(t.nodes[v]);
      out.simplified.tree.values.push_back(t.values[v]);
      out.simplified.kept.push_back(v);
    }
  for (const Arc &a : arcs)
    if (a.alive)
      out.simplified.tree.arcs.push_back({index[a.lo], index[a.hi]});
  std::sort(out.simplified.tree.arcs.begin(), out.simplified.tree.arcs.end());
  out.simplified.pruned_leaves = static_cast<int64_t>(order.size());
  prune(INFINITY);
  // The root: the last arc left by (lower node, upper node, id); ids in order of creation.
  int64_t root = -1;
  for (std::size_t k = 0; k < arcs.size(); ++k)
    if (arcs[k].alive &&
        (root < 0 || std::tie(arcs[k].lo, arcs[k].hi) >= std::tie(arcs[root].lo, arcs[root].hi)))
      root = static_cast<int64_t>(k);
  std::vector<int64_t> owner(n, 0); // the branch whose arc holds a spliced node
  if (root >= 0)
    out.branches.push_back(
        {arcs[root].hi, arcs[root].lo, t.values[arcs[root].hi] - t.values[arcs[root].lo], -1, 0});
  else
    out.branches.push_back({-1, -1, 0.0, -1, 0});
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    for (int64_t x : arcs[it->arc].inside)
      owner[x] = static_cast<int64_t>(out.branches.size());
    out.branches.push_back({it->leaf, it->saddle, it->persistence, -1, 0});
  }
  for (std::size_t b = 1; b < out.branches.size(); ++b) {
    out.branches[b].parent = owner[out.branches[b].saddle];
    out.branches[b].depth = out.branches[out.branches[b].parent].depth + 1;
  }
  return out;
}

// A random forest on n nodes (`components` trees) plus `extra` arcs (loops, parallel arcs);
// values from `levels` distinct ones (0: continuous); nodes numbered in the total order.
ContourTree random_graph(std::mt19937_64 &rng, int n, int levels, int extra, int components) {
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<double> value(n);
  for (auto &v : value)
    v = levels > 0 ? std::floor(U(rng) * levels) : U(rng);
  std::vector<std::array<int64_t, 2>> edges;
  for (int i = 1; i < n; ++i)
    if (i % components != 0 || i < components) {
      // Mostly recent nodes (long paths), sometimes any (bushy trees).
      const int lo = rng() % 4 == 0 ? 0 : std::max(0, i - 4);
      edges.push_back({std::uniform_int_distribution<int64_t>(lo, i - 1)(rng), i});
    }
  for (int e = 0; e < extra; ++e) {
    const int64_t a = static_cast<int64_t>(rng() % n), b = static_cast<int64_t>(rng() % n);
    if (a != b)
      edges.push_back({a, b});
  }
  // Shuffle the labels, then number the nodes by (value, label).
  std::vector<int64_t> label(n), order(n), rank(n);
  std::iota(label.begin(), label.end(), int64_t{0});
  std::shuffle(label.begin(), label.end(), rng);
  std::iota(order.begin(), order.end(), int64_t{0});
  std::sort(order.begin(), order.end(), [&](int64_t x, int64_t y) {
    return std::tie(value[x], label[x]) < std::tie(value[y], label[y]);
  });
  ContourTree t;
  for (int64_t i = 0; i < n; ++i) {
    rank[order[i]] = i;
    t.nodes.push_back(label[order[i]]);
    t.values.push_back(value[order[i]]);
  }
  for (const auto &e : edges)
    t.arcs.push_back({std::min(rank[e[0]], rank[e[1]]), std::max(rank[e[0]], rank[e[1]])});
  std::sort(t.arcs.begin(), t.arcs.end());
  return t;
}

void expect_same_branches(const std::vector<Branch> &got, const std::vector<Branch> &want,
                          const std::string &what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t b = 0; b < got.size(); ++b) {
    EXPECT_EQ(got[b].extremum, want[b].extremum) << what << " branch " << b;
    EXPECT_EQ(got[b].saddle, want[b].saddle) << what << " branch " << b;
    EXPECT_EQ(got[b].persistence, want[b].persistence) << what << " branch " << b;
    EXPECT_EQ(got[b].parent, want[b].parent) << what << " branch " << b;
    EXPECT_EQ(got[b].depth, want[b].depth) << what << " branch " << b;
  }
}

TEST(LeafPruning, MatchesTheQuadraticReference) {
  std::mt19937_64 rng(32);
  int with_ties = 0, deep = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int n = 1 + static_cast<int>(rng() % (trial % 5 == 0 ? 200 : 24));
    const int levels = std::array{0, 2, 3, 5, 20}[rng() % 5];
    const int extra = rng() % 4 == 0 ? static_cast<int>(rng() % 4) : 0;
    const int components = rng() % 6 == 0 ? 2 + static_cast<int>(rng() % 3) : 1;
    ContourTree t = random_graph(rng, n, levels, extra, components);
    if (extra == 0 && components == 1 && rng() % 2)
      t = reduce(t);
    const std::string what = "trial " + std::to_string(trial);
    const std::vector<Branch> branches = branch_decomposition(t.values, t.arcs);
    for (double threshold : {0.0, 0.15, 1.0, 2.5, double(INFINITY)}) {
      const Reference ref = reference_pruning(t, threshold);
      const Simplification s = simplify(t, threshold);
      EXPECT_EQ(s.tree.nodes, ref.simplified.tree.nodes) << what;
      EXPECT_EQ(s.tree.values, ref.simplified.tree.values) << what;
      EXPECT_EQ(s.tree.arcs, ref.simplified.tree.arcs) << what;
      EXPECT_EQ(s.kept, ref.simplified.kept) << what;
      EXPECT_EQ(s.pruned_leaves, ref.simplified.pruned_leaves) << what;
      expect_same_branches(s.branches, ref.branches, what);
      if (threshold == 0)
        expect_same_branches(branches, ref.branches, what + " (branch_decomposition)");
    }
    with_ties += levels > 0 && n > levels;
    for (const Branch &b : branches)
      deep += b.depth >= 2;
  }
  // The trials exercise what they are for.
  EXPECT_GT(with_ties, 500);
  EXPECT_GT(deep, 100);
}

TEST(LeafPruning, RejectsArcsNotFromLowerToUpperNode) {
  const std::vector<double> values{0, 1, 2};
  const std::vector<std::array<int64_t, 2>> down{{0, 1}, {2, 1}}, loop{{0, 1}, {1, 1}};
  EXPECT_THROW(branch_decomposition(values, down), std::invalid_argument);
  EXPECT_THROW(branch_decomposition(values, loop), std::invalid_argument);
}

} // namespace
} // namespace hoct
