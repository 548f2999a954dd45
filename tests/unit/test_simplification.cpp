// Persistence simplification against its brute-force reference: the simplified tree's diagram is
// the original diagram minus the pairs below the threshold; and the branch decomposition.
#include "pl/pl_mesh.hpp"
#include "test_meshes.hpp"
#include "tree/contour_tree.hpp"
#include "tree/flat_regions.hpp"
#include "tree/simplification.hpp"
#include "tree/tree_result.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace hoct {
namespace {

using Points = std::vector<std::array<double, 2>>;

Points kind_points(const std::vector<PersistencePair> &pairs, PersistencePair::Kind k,
                   double min_persistence) {
  Points p;
  for (const auto &x : pairs)
    if (x.kind == k && x.persistence() >= min_persistence)
      p.push_back({x.birth_value, x.death_value});
  std::sort(p.begin(), p.end());
  return p;
}

void check_valid(const ContourTree &t) {
  ASSERT_EQ(static_cast<int64_t>(t.arcs.size()), t.size() - 1);
  const auto deg = t.degrees();
  int64_t sum = 0;
  for (const auto &d : deg) {
    sum += d[0] + d[1] - 2;
    EXPECT_FALSE(d[0] == 1 && d[1] == 1) << "a regular node was left";
  }
  EXPECT_EQ(sum, -2);
}

TEST(Simplification, DiagramLosesExactlyThePairsBelowTheThreshold) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(0, 1);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<Vec3> v;
    std::vector<std::array<int64_t, 3>> t;
    if (trial % 2)
      testing::octahedron(4, v, t);
    else
      testing::square_grid(8, rng, v, t);
    PlMesh m;
    m.points = v;
    for (std::size_t i = 0; i < v.size(); ++i)
      m.values.push_back(U(rng) + 0.7 * std::sin(4 * v[i][0]) * std::cos(3 * v[i][1]));
    m.triangles = t;
    const ContourTree ct = contour_tree(m.graph());
    const auto pairs = tree_pairs(ct);
    std::vector<double> pers;
    for (const auto &p : pairs)
      pers.push_back(p.persistence());
    std::sort(pers.begin(), pers.end());
    for (double q : {0.0, 0.1, 0.3, 0.5, 0.8, 0.95}) {
      const double threshold = q == 0 ? 0.0 : pers[static_cast<std::size_t>(q * (pers.size() - 1))];
      const Simplification s = simplify(ct, threshold);
      check_valid(s.tree);
      const auto after = tree_pairs(s.tree);
      for (auto k : {PersistencePair::Kind::Join, PersistencePair::Kind::Split,
                     PersistencePair::Kind::Global})
        EXPECT_EQ(kind_points(after, k, 0), kind_points(pairs, k, threshold))
            << "trial " << trial << " threshold " << threshold << " " << to_string(k);
      int64_t leaves = 0, above = 0;
      for (const auto &d : s.tree.degrees())
        leaves += d[0] + d[1] == 1;
      for (const auto &p : pairs)
        above += p.persistence() >= threshold;
      EXPECT_EQ(leaves, above + 1);
      // Kept nodes keep their values.
      for (int64_t i = 0; i < s.tree.size(); ++i)
        EXPECT_EQ(s.tree.values[i], ct.values[s.kept[i]]);
    }
    // The branch decomposition: one branch per pair, the root spanning the whole range.
    const Simplification full = simplify(ct, 0);
    ASSERT_EQ(full.branches.size(), pairs.size());
    std::vector<double> bp;
    for (const auto &b : full.branches)
      bp.push_back(b.persistence);
    std::sort(bp.begin(), bp.end());
    EXPECT_EQ(bp, pers);
    EXPECT_EQ(full.branches[0].parent, -1);
    EXPECT_DOUBLE_EQ(full.branches[0].persistence, ct.values.back() - ct.values.front());
    for (std::size_t b = 1; b < full.branches.size(); ++b) {
      const Branch &br = full.branches[b];
      ASSERT_GE(br.parent, 0);
      ASSERT_LT(br.parent, static_cast<int64_t>(b));
      EXPECT_EQ(br.depth, full.branches[br.parent].depth + 1);
      EXPECT_LE(br.persistence, full.branches[br.parent].persistence + 1e-15);
      // The saddle of a branch lies within the value range of its parent branch.
      const Branch &p = full.branches[br.parent];
      const double lo = std::min(ct.values[p.extremum], ct.values[p.saddle]);
      const double hi = std::max(ct.values[p.extremum], ct.values[p.saddle]);
      EXPECT_GE(ct.values[br.saddle], lo);
      EXPECT_LE(ct.values[br.saddle], hi);
    }
  }
}

TEST(FlatRegions, ContractionKeepsEveryPairOfPositivePersistence) {
  // Values on a few levels: many plateaus, ties broken by id, zero-persistence pairs.
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<Vec3> v;
    std::vector<std::array<int64_t, 3>> t;
    if (trial % 2)
      testing::octahedron(4, v, t);
    else
      testing::square_grid(9, rng, v, t);
    PlMesh m;
    m.points = v;
    for (const auto &p : v)
      m.values.push_back(std::round(3 * std::sin(5 * p[0]) * std::cos(4 * p[1]) + p[2]));
    m.triangles = t;
    const ContourTree ct = contour_tree(m.graph());
    const FlatContraction f = contract_flat_arcs(ct);
    check_valid(f.tree);
    for (const auto &a : f.tree.arcs)
      EXPECT_NE(f.tree.values[a[0]], f.tree.values[a[1]]);
    const auto before = tree_pairs(ct), after = tree_pairs(f.tree);
    for (auto k : {PersistencePair::Kind::Join, PersistencePair::Kind::Split}) {
      // Zero-persistence pairs disappear, every other pair stays.
      EXPECT_EQ(kind_points(after, k, 0), kind_points(before, k, 1e-300)) << "trial " << trial;
    }
    for (const auto &p : after)
      EXPECT_GT(p.persistence(), 0);
    EXPECT_LT(f.tree.size(), ct.size());
    for (std::size_t i = 0; i < f.kept.size(); ++i)
      EXPECT_EQ(f.tree.values[i], ct.values[f.kept[i]]);
  }
}

} // namespace
} // namespace hoct
