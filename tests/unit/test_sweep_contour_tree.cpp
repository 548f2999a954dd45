// sweep_contour_tree (rank space, regular nodes spliced out before the merge) against the
// ScalarGraph path (join_tree, split_tree, merge_trees, reduce), which test_contour_tree checks
// against brute force: random graphs with tied values, duplicate edges, self-loops, several
// components, and join and split edge sets that differ, as in the exact tree.
#include "tree/contour_tree.hpp"
#include "tree/merge_tree.hpp"
#include "tree/sweep_contour_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <span>
#include <stdexcept>

namespace hoct {
namespace {

struct RandomGraph {
  std::vector<double> values;
  std::vector<GraphEdge> common, join, split; // join / split: the extra edges of each sweep

  std::vector<GraphEdge> all_join() const { return concat(join); }
  std::vector<GraphEdge> all_split() const { return concat(split); }

private:
  std::vector<GraphEdge> concat(const std::vector<GraphEdge> &extra) const {
    std::vector<GraphEdge> all = common;
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
  }
};

// The 1-skeleton of `components` triangulated grids (disks: their level sets form a tree) with
// random values (many ties when distinct_values is small), a few duplicate edges and
// self-loops. The join edges add shortcuts along descending paths, the split edges along
// ascending ones (as the exact tree's certified connections do): the edge sets differ, their
// sublevel and superlevel sets connect alike.
RandomGraph random_graph(std::mt19937_64 &rng, int components, int distinct_values) {
  RandomGraph g;
  std::uniform_int_distribution<int> value(0, distinct_values - 1), side(1, 14);
  std::vector<GraphEdge> edges;
  for (int c = 0; c < components; ++c) {
    const int64_t w = side(rng), h = side(rng), base = static_cast<int64_t>(g.values.size());
    for (int64_t k = 0; k < w * h; ++k)
      g.values.push_back(value(rng) * 0.5 - 3);
    auto id = [&](int64_t i, int64_t j) { return base + j * w + i; };
    for (int64_t j = 0; j < h; ++j)
      for (int64_t i = 0; i < w; ++i) {
        if (i + 1 < w)
          edges.push_back({id(i, j), id(i + 1, j)});
        if (j + 1 < h)
          edges.push_back({id(i, j + 1), id(i, j)});
        if (i + 1 < w && j + 1 < h)
          edges.push_back(rng() % 2 ? GraphEdge{id(i, j), id(i + 1, j + 1)}
                                    : GraphEdge{id(i + 1, j), id(i, j + 1)});
      }
  }
  const int64_t n = static_cast<int64_t>(g.values.size());
  for (int k = 0; k < 5; ++k) {
    if (!edges.empty()) {
      const GraphEdge copy = edges[rng() % edges.size()];
      edges.push_back(copy); // duplicates
    }
    const int64_t v = static_cast<int64_t>(rng() % n);
    edges.push_back({v, v}); // self-loops
  }
  std::vector<std::vector<int64_t>> adj(n);
  for (const GraphEdge &e : edges) {
    adj[e.a].push_back(e.b);
    adj[e.b].push_back(e.a);
  }
  g.common = edges;
  for (int64_t k = 0; k < n; ++k) {
    const int64_t start = static_cast<int64_t>(rng() % n);
    for (bool down : {true, false}) {
      int64_t v = start;
      for (int step = 0; step < 6; ++step) { // a random monotone walk
        std::vector<int64_t> next;
        for (int64_t w : adj[v])
          if (down ? node_less(g.values[w], w, g.values[v], v)
                   : node_less(g.values[v], v, g.values[w], w))
            next.push_back(w);
        if (next.empty())
          break;
        v = next[rng() % next.size()];
      }
      (down ? g.join : g.split).push_back({start, v});
    }
  }
  std::shuffle(g.common.begin(), g.common.end(), rng);
  return g;
}

ContourTree reference(const RandomGraph &g, bool augmented) {
  const ScalarGraph jg(g.values, g.all_join()), sg(g.values, g.all_split());
  const ContourTree aug = merge_trees(jg, join_tree(jg), split_tree(sg));
  return augmented ? aug : reduce(aug);
}

void expect_same(const ContourTree &a, const ContourTree &b) {
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.arcs, b.arcs);
}

TEST(SweepContourTree, MatchesTheScalarGraphPathOnRandomGraphs) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const int components = 1 + static_cast<int>(rng() % 3);
    const int distinct = trial % 3 == 0 ? 3 : 1000; // many ties, or few
    const RandomGraph g = random_graph(rng, components, distinct);
    const std::size_t n = g.values.size();
    for (bool augmented : {false, true})
      for (int threads : {1, 2}) {
        SCOPED_TRACE(testing::Message() << "trial " << trial << " n " << n << " augmented "
                                        << augmented << " threads " << threads);
        const ContourTree expected = reference(g, augmented);
        expect_same(sweep_contour_tree(g.values, {g.common, g.join, g.split}, augmented, threads),
                    expected);
        // The same edges, none marked common.
        const auto join = g.all_join(), split = g.all_split();
        expect_same(sweep_contour_tree(g.values, {{}, join, split}, augmented, threads), expected);
        expect_same(
            sweep_contour_tree_wide(g.values, {g.common, g.join, g.split}, augmented, threads),
            expected);
      }
  }
}

// Chains (the exact tree's mesh edges with their edge nodes) walked by the sweeps against the
// same pieces listed as common edges: random graphs whose common edges become chains through 0-3
// new nodes each (values strictly monotone from one end to the other, so that the join and split
// shortcuts still follow monotone paths), some chains skipped and listed instead (their ends in
// the chains say a node of their own, isolated otherwise: walking a skipped chain would show).
TEST(SweepContourTree, ChainsEqualTheirListedPieces) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    RandomGraph g = random_graph(rng, 1 + static_cast<int>(rng() % 2), trial % 2 ? 4 : 1000);
    const int64_t first = static_cast<int64_t>(g.values.size());
    std::vector<std::array<int64_t, 2>> ends;
    std::vector<int64_t> offset{0}, skip;
    std::vector<GraphEdge> pieces, kept; // all chain pieces; the skipped chains' pieces
    const std::size_t old_nodes = g.values.size();
    for (const GraphEdge &e : g.common) {
      const double va = g.values[e.a], vb = g.values[e.b];
      const int inner = va == vb ? 0 : static_cast<int>(rng() % 4);
      const bool skipped = rng() % 5 == 0;
      if (skipped)
        skip.push_back(static_cast<int64_t>(ends.size()));
      ends.push_back({e.a, skipped ? int64_t{-1} : e.b}); // -1: the isolated node, set below
      int64_t prev = e.a;
      for (int k = 0; k < inner; ++k) {
        const int64_t id = first + offset.back() + k;
        g.values.push_back(va + (vb - va) * (k + 1) / (inner + 1));
        (skipped ? kept : pieces).push_back({prev, id});
        prev = id;
      }
      (skipped ? kept : pieces).push_back({prev, e.b});
      offset.push_back(offset.back() + inner);
    }
    ASSERT_EQ(g.values.size(), old_nodes + static_cast<std::size_t>(offset.back()));
    const int64_t isolated = static_cast<int64_t>(g.values.size());
    g.values.push_back(0.25);
    for (auto &e : ends)
      if (e[1] < 0)
        e[1] = isolated;
    RandomGraph listed_graph = g;
    listed_graph.common = pieces;
    listed_graph.common.insert(listed_graph.common.end(), kept.begin(), kept.end());
    SweepEdges chains{kept, g.join, g.split, {ends, offset, first, skip}};
    for (bool augmented : {false, true})
      for (int threads : {1, 2}) {
        SCOPED_TRACE(testing::Message()
                     << "trial " << trial << " augmented " << augmented << " threads " << threads);
        const ContourTree expected = reference(listed_graph, augmented);
        expect_same(sweep_contour_tree(g.values, chains, augmented, threads), expected);
        expect_same(sweep_contour_tree_wide(g.values, chains, augmented, threads), expected);
      }
  }
}

TEST(SweepContourTree, RejectsInconsistentChains) {
  const std::vector<double> values{0, 1, 2, 3};
  const std::vector<std::array<int64_t, 2>> ends{{0, 1}, {1, 2}}, far{{0, 4}, {1, 2}};
  const std::vector<int64_t> offset{0, 1, 2}, short_offset{0, 1}, descending{0, 2, 1},
      too_many{0, 1, 3}, skip_twice{1, 1}, skip_beyond{2};
  auto run = [&](std::span<const std::array<int64_t, 2>> e, std::span<const int64_t> o,
                 int64_t first, std::span<const int64_t> skip = {}) {
    return sweep_contour_tree(values, {{}, {}, {}, {e, o, first, skip}}, false);
  };
  EXPECT_NO_THROW(run(ends, offset, 2));
  EXPECT_THROW(run(ends, short_offset, 2), std::invalid_argument);
  EXPECT_THROW(run(ends, descending, 2), std::invalid_argument);
  EXPECT_THROW(run(ends, too_many, 2), std::out_of_range); // nodes 2..4 of 4
  EXPECT_THROW(run(ends, offset, 3), std::out_of_range);   // nodes 3..4 of 4
  EXPECT_THROW(run(far, offset, 2), std::out_of_range);    // an end beyond the nodes
  EXPECT_THROW(run(ends, offset, 2, skip_twice), std::invalid_argument);
  EXPECT_THROW(run(ends, offset, 2, skip_beyond), std::invalid_argument);
}

TEST(SweepContourTree, LargeGraphOnTwoThreadsMatches) {
  // Above the size where the order is sorted in two halves and merged.
  std::mt19937_64 rng(11);
  RandomGraph g;
  while (g.values.size() < 70000) { // several graphs side by side
    RandomGraph part = random_graph(rng, 3, 5000);
    const int64_t base = static_cast<int64_t>(g.values.size());
    g.values.insert(g.values.end(), part.values.begin(), part.values.end());
    for (auto [list, add] : {std::pair{&g.common, &part.common}, std::pair{&g.join, &part.join},
                             std::pair{&g.split, &part.split}})
      for (const GraphEdge &e : *add)
        list->push_back({base + e.a, base + e.b});
  }
  expect_same(sweep_contour_tree(g.values, {g.common, g.join, g.split}, false, 2),
              reference(g, false));
  expect_same(sweep_contour_tree(g.values, {g.common, g.join, g.split}, true, 1),
              reference(g, true));
}

TEST(NodeTotalOrder, AscendingOrderBreaksTiesById) {
  const std::vector<double> values{2, 1, 2, 1, -0.0, 0.0, 1};
  const std::vector<int64_t> expected{4, 5, 1, 3, 6, 0, 2};
  EXPECT_EQ(ascending_order(values), expected);
  EXPECT_TRUE(ascending_order(std::vector<double>{}).empty());
}

TEST(NodeTotalOrder, PartitionSortEqualsComparisonSort) {
  // Values of every sign and magnitude (denormals, infinities, many ties): the radix sort of
  // the bit patterns against std::sort with the total order (1.1M keys: the 16-bit first pass;
  // 300,000 and 1.1M keys also on threads).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-1074, 1023), kind(0, 9);
  for (std::size_t n : {1u, 2u, 17u, 1000u, 100000u, 300000u, 1100000u}) {
    std::vector<double> v(n);
    for (double &x : v) {
      const int k = kind(rng);
      x = k == 0   ? std::ldexp(mantissa(rng), exponent(rng))
          : k == 1 ? (rng() % 2 ? INFINITY : -INFINITY)
          : k == 2 ? (rng() % 2 ? 0.0 : -0.0)
          : k <= 5 ? static_cast<double>(rng() % 7) - 3
                   : mantissa(rng) * 1e3;
    }
    std::vector<int64_t> expected(n);
    for (std::size_t i = 0; i < n; ++i)
      expected[i] = static_cast<int64_t>(i);
    std::sort(expected.begin(), expected.end(),
              [&](int64_t a, int64_t b) { return node_less(v[a], a, v[b], b); });
    EXPECT_EQ(ascending_order(v), expected) << n;
    // On threads (from 65,536 keys): the first partition's parts sorted side by side.
    for (int threads : {2, 3})
      EXPECT_EQ(ascending_order(v, threads), expected) << n << " keys, " << threads << " threads";
  }
}

TEST(SweepContourTree, RejectsEdgesOutOfRange) {
  const std::vector<double> values{0, 1};
  const std::vector<GraphEdge> bad{{0, 2}}, good{{0, 1}};
  EXPECT_THROW(sweep_contour_tree(values, {bad, good, good}, false), std::out_of_range);
  EXPECT_THROW(sweep_contour_tree(values, {good, bad, good}, false), std::out_of_range);
  EXPECT_THROW(sweep_contour_tree(values, {good, good, bad}, false), std::out_of_range);
}

} // namespace
} // namespace hoct
