// Join, split and contour trees of PL fields against brute force: components of sublevel,
// superlevel and level sets counted directly on the mesh for every level.
#include "pl/pl_mesh.hpp"
#include "test_meshes.hpp"
#include "tree/contour_tree.hpp"
#include "tree/merge_tree.hpp"
#include "tree/persistence.hpp"
#include "tree/union_find.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <set>

namespace hoct {
namespace {

PlMesh random_pl_mesh(bool sphere, int n, std::mt19937_64 &rng, int levels = 0) {
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  if (sphere)
    testing::octahedron(n, v, t);
  else
    testing::square_grid(n, rng, v, t);
  std::uniform_real_distribution<double> U(0, 1);
  PlMesh m;
  m.points = v;
  for (std::size_t i = 0; i < v.size(); ++i)
    m.values.push_back(levels > 0 ? static_cast<double>(rng() % levels) : U(rng));
  m.triangles = t;
  return m;
}

// Components of the nodes with rank < r (ascending) in the graph, by BFS.
int components_below(const ScalarGraph &g, const std::vector<int64_t> &rank, int64_t r) {
  UnionFind uf(g.size());
  int comps = 0;
  for (int64_t v = 0; v < g.size(); ++v) {
    if (rank[v] >= r)
      continue;
    ++comps;
    for (int64_t u : g.neighbors(v))
      if (rank[u] < r && uf.unite(u, v))
        --comps;
  }
  return comps;
}

// Components of the level set at c (no vertex has value c): crossing edges joined in triangles.
int level_set_components(const PlMesh &m, double c) {
  std::map<std::pair<int64_t, int64_t>, int64_t> id;
  std::vector<std::pair<int64_t, int64_t>> links;
  auto edge_id = [&](int64_t a, int64_t b) {
    auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = id.find(key);
    if (it != id.end())
      return it->second;
    const int64_t k = static_cast<int64_t>(id.size());
    id[key] = k;
    return k;
  };
  for (const auto &t : m.triangles) {
    std::vector<int64_t> crossing;
    for (int k = 0; k < 3; ++k) {
      const int64_t a = t[k], b = t[(k + 1) % 3];
      if ((m.values[a] < c) != (m.values[b] < c))
        crossing.push_back(edge_id(a, b));
    }
    if (crossing.size() == 2)
      links.emplace_back(crossing[0], crossing[1]);
  }
  UnionFind uf(id.size());
  int comps = static_cast<int>(id.size());
  for (auto [a, b] : links)
    if (uf.unite(a, b))
      --comps;
  return comps;
}

// Elder rule by brute force: a minimum dies at the lowest rank at which its sublevel component
// reaches a node lower than itself; ranks are given, so the split case reuses it reversed.
std::set<std::pair<int64_t, int64_t>> brute_join_pairs(const ScalarGraph &g,
                                                       const std::vector<int64_t> &rank) {
  const int64_t n = g.size();
  std::vector<int64_t> node(n);
  for (int64_t v = 0; v < n; ++v)
    node[rank[v]] = v;
  std::set<std::pair<int64_t, int64_t>> pairs;
  for (int64_t m = 0; m < n; ++m) {
    bool is_min = true;
    for (int64_t u : g.neighbors(m))
      is_min = is_min && rank[u] > rank[m];
    if (!is_min)
      continue;
    for (int64_t r = rank[m]; r < n; ++r) {
      // Component of m among ranks <= r.
      std::vector<char> seen(n, 0);
      std::vector<int64_t> stack = {m};
      seen[m] = 1;
      bool older = false;
      while (!stack.empty()) {
        const int64_t v = stack.back();
        stack.pop_back();
        older = older || rank[v] < rank[m];
        for (int64_t u : g.neighbors(v))
          if (!seen[u] && rank[u] <= r) {
            seen[u] = 1;
            stack.push_back(u);
          }
      }
      if (older) {
        pairs.insert({m, node[r]});
        break;
      }
    }
  }
  return pairs;
}

void check_trees(const PlMesh &m) {
  const ScalarGraph g = m.graph();
  const int64_t n = g.size();
  std::vector<int64_t> rank(n);
  for (int64_t i = 0; i < n; ++i)
    rank[g.ascending()[i]] = i;
  const MergeTree jt = join_tree(g), st = split_tree(g);
  // Join tree: components of {rank < r} = nodes below r whose parent is at or above r.
  for (int64_t r = 1; r <= n; ++r) {
    int64_t arcs = 0, arcs_up = 0;
    for (int64_t v = 0; v < n; ++v) {
      if (rank[v] < r && (jt.parent[v] < 0 || rank[jt.parent[v]] >= r))
        ++arcs;
      if (rank[v] >= n - r && (st.parent[v] < 0 || rank[st.parent[v]] < n - r))
        ++arcs_up;
    }
    ASSERT_EQ(arcs, components_below(g, rank, r)) << "join tree, level rank " << r;
    // Superlevel: the top r nodes, i.e. ranks >= n - r, = components of the reversed ranks.
    std::vector<int64_t> rev(n);
    for (int64_t v = 0; v < n; ++v)
      rev[v] = n - 1 - rank[v];
    ASSERT_EQ(arcs_up, components_below(g, rev, r)) << "split tree, level rank " << r;
  }
  // Contour tree: at every level between distinct consecutive values, contours = arcs crossing.
  const ContourTree aug = contour_tree(g, /*augmented=*/true);
  ASSERT_EQ(aug.size(), n);
  ASSERT_EQ(static_cast<int64_t>(aug.arcs.size()), n - 1);
  std::vector<double> sorted = m.values;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i) {
    const double c = 0.5 * (sorted[i] + sorted[i + 1]);
    int crossing = 0;
    for (const auto &a : aug.arcs)
      crossing += aug.values[a[0]] < c && c < aug.values[a[1]];
    ASSERT_EQ(crossing, level_set_components(m, c)) << "level " << c;
  }
  // An independent per-vertex classification from the link: the number of lower (upper) link
  // components bounds the augmented tree's down (up) degree, with equality for regular vertices
  // (one of each) and for extrema (none below or above).
  {
    std::vector<std::vector<std::array<int64_t, 2>>> link(n); // link edges of each vertex
    for (const auto &t : m.triangles)
      for (int k = 0; k < 3; ++k)
        link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
    const auto deg = aug.degrees();
    std::vector<int64_t> index(n);
    for (int64_t i = 0; i < n; ++i)
      index[aug.nodes[i]] = i;
    for (int64_t v = 0; v < n; ++v) {
      int comps[2] = {0, 0}; // lower, upper
      for (int side = 0; side < 2; ++side) {
        std::map<int64_t, int64_t> parent;
        auto find = [&](int64_t x) {
          while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
          return x;
        };
        auto on_side = [&](int64_t u) { return side == 0 ? g.less(u, v) : g.less(v, u); };
        for (int64_t u : g.neighbors(v))
          if (on_side(u))
            parent[u] = u;
        int c = static_cast<int>(parent.size());
        for (const auto &e : link[v])
          if (on_side(e[0]) && on_side(e[1]) && find(e[0]) != find(e[1])) {
            parent[find(e[0])] = find(e[1]);
            --c;
          }
        comps[side] = c;
      }
      const auto d = deg[index[v]]; // {up, down}
      EXPECT_LE(d[1], comps[0]) << "vertex " << v;
      EXPECT_LE(d[0], comps[1]) << "vertex " << v;
      if (comps[0] == 1 && comps[1] == 1) {
        EXPECT_EQ(d[1], 1);
        EXPECT_EQ(d[0], 1);
      }
      if (comps[0] == 0) {
        EXPECT_EQ(d[1], 0);
      }
      if (comps[1] == 0) {
        EXPECT_EQ(d[0], 0);
      }
    }
  }
  // Reduced tree invariants: a tree, sum(deg - 2) = -2, leaves = local extrema of the mesh.
  const ContourTree ct = reduce(aug);
  ASSERT_EQ(static_cast<int64_t>(ct.arcs.size()), ct.size() - 1);
  const auto deg = ct.degrees();
  int64_t sum = 0;
  std::set<int64_t> leaves;
  for (int64_t i = 0; i < ct.size(); ++i) {
    const int d = deg[i][0] + deg[i][1];
    sum += d - 2;
    EXPECT_NE(d, 0);
    if (d == 1)
      leaves.insert(ct.nodes[i]);
  }
  EXPECT_EQ(sum, -2);
  std::set<int64_t> extrema;
  for (int64_t v = 0; v < n; ++v) {
    bool lowest = true, highest = true;
    for (int64_t u : g.neighbors(v)) {
      if (g.less(u, v))
        lowest = false;
      else
        highest = false;
    }
    if (lowest || highest)
      extrema.insert(v);
  }
  EXPECT_EQ(leaves, extrema);
  // Types agree with an independent per-vertex count of lower-link components for maxima and
  // minima, and every node of the reduced tree keeps its value.
  const auto types = ct.types();
  for (int64_t i = 0; i < ct.size(); ++i) {
    EXPECT_EQ(ct.values[i], m.values[ct.nodes[i]]);
    if (deg[i][0] + deg[i][1] == 1) {
      const bool is_min = deg[i][1] == 0;
      EXPECT_EQ(types[i], is_min ? NodeType::Minimum : NodeType::Maximum);
    }
  }
  // The elder rule against brute force.
  {
    const auto d = persistence_diagram(g);
    std::set<std::pair<int64_t, int64_t>> join, split;
    for (const auto &p : d.pairs) {
      if (p.kind == PersistencePair::Kind::Join)
        join.insert({p.birth, p.death});
      if (p.kind == PersistencePair::Kind::Split)
        split.insert({p.birth, p.death});
    }
    EXPECT_EQ(join, brute_join_pairs(g, rank));
    std::vector<int64_t> rev(n);
    for (int64_t v = 0; v < n; ++v)
      rev[v] = n - 1 - rank[v];
    EXPECT_EQ(split, brute_join_pairs(g, rev));
  }
  // The diagram of the field equals the diagram of its contour tree (viewed as a graph).
  std::vector<GraphEdge> tree_edges;
  for (const auto &a : ct.arcs)
    tree_edges.push_back({a[0], a[1]});
  std::vector<double> tv = ct.values;
  // Same tie-breaking: node ids ascending in the reduced tree follow the graph's order.
  const ScalarGraph tg(tv, tree_edges);
  const auto d1 = persistence_diagram(g), d2 = persistence_diagram(tg);
  for (auto kind :
       {PersistencePair::Kind::Join, PersistencePair::Kind::Split, PersistencePair::Kind::Global}) {
    auto p1 = d1.points(kind), p2 = d2.points(kind);
    std::sort(p1.begin(), p1.end());
    std::sort(p2.begin(), p2.end());
    EXPECT_EQ(p1, p2) << to_string(kind);
  }
}

TEST(ContourTree, RandomFieldsOnDisksMatchBruteForce) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 6; ++trial)
    check_trees(random_pl_mesh(false, 4 + trial, rng));
}

TEST(ContourTree, RandomFieldsOnSpheresMatchBruteForce) {
  std::mt19937_64 rng(43);
  for (int trial = 0; trial < 4; ++trial)
    check_trees(random_pl_mesh(true, 2 + trial, rng));
}

TEST(ContourTree, PlateausAndEqualValuesUseTheTotalOrder) {
  // Values from {0, 1, 2}: many ties, broken by vertex id. Level-set counts are only checked
  // between distinct values, the sweeps at every rank.
  std::mt19937_64 rng(44);
  for (int trial = 0; trial < 4; ++trial) {
    check_trees(random_pl_mesh(false, 5, rng, 3));
    check_trees(random_pl_mesh(true, 3, rng, 2));
  }
}

TEST(ContourTree, MonkeySaddleIsOneNodeOfDegreeFour) {
  // A hexagon fan around a centre of value 0 with alternating +-1: a multi-saddle of degree 6
  // in the augmented tree's sense (3 lower, 3 upper contours).
  PlMesh m;
  m.points.push_back({0, 0, 0});
  m.values.push_back(0);
  for (int i = 0; i < 6; ++i) {
    m.points.push_back({std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), 0});
    m.values.push_back(i % 2 ? 1.0 + 0.1 * i : -1.0 - 0.1 * i);
  }
  for (int i = 0; i < 6; ++i)
    m.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  const ContourTree ct = contour_tree(m.graph());
  const auto deg = ct.degrees();
  const auto types = ct.types();
  int saddles = 0;
  for (int64_t i = 0; i < ct.size(); ++i)
    if (types[i] == NodeType::Saddle) {
      ++saddles;
      EXPECT_EQ(ct.nodes[i], 0);
      EXPECT_EQ(deg[i][0], 3);
      EXPECT_EQ(deg[i][1], 3);
    }
  EXPECT_EQ(saddles, 1);
  EXPECT_EQ(ct.size(), 7);
  check_trees(m);
}

// Brute-force bottleneck: all bijections of the diagonal-augmented point sets.
double brute_bottleneck(const std::vector<std::array<double, 2>> &a,
                        const std::vector<std::array<double, 2>> &b) {
  const int n = static_cast<int>(a.size()), m = static_cast<int>(b.size());
  std::vector<int> perm(n + m);
  std::iota(perm.begin(), perm.end(), 0);
  double best = INFINITY;
  auto cost = [&](int i, int j) {
    // left: a[0..n) then diagonal copies of b; right: b[0..m) then diagonal copies of a.
    const bool li = i < n, rj = j < m;
    if (li && rj)
      return std::max(std::abs(a[i][0] - b[j][0]), std::abs(a[i][1] - b[j][1]));
    if (li && !rj)
      return j - m == i ? std::abs(a[i][1] - a[i][0]) / 2 : INFINITY;
    if (!li && rj)
      return i - n == j ? std::abs(b[j][1] - b[j][0]) / 2 : INFINITY;
    return 0.0;
  };
  do {
    double worst = 0;
    for (int i = 0; i < n + m; ++i)
      worst = std::max(worst, cost(i, perm[i]));
    best = std::min(best, worst);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

TEST(Persistence, BottleneckMatchesBruteForce) {
  std::mt19937_64 rng(45);
  std::uniform_real_distribution<double> U(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = static_cast<int>(rng() % 4), m = static_cast<int>(rng() % 4);
    std::vector<std::array<double, 2>> a, b;
    for (int i = 0; i < n; ++i) {
      const double x = U(rng);
      a.push_back({x, x + U(rng)});
    }
    for (int i = 0; i < m; ++i) {
      const double x = U(rng);
      b.push_back({x, x + U(rng)});
    }
    EXPECT_DOUBLE_EQ(bottleneck_distance(a, b), brute_bottleneck(a, b)) << "trial " << trial;
  }
  EXPECT_EQ(bottleneck_distance({}, {}), 0.0);
  EXPECT_DOUBLE_EQ(bottleneck_distance({{0, 1}}, {}), 0.5);
  EXPECT_DOUBLE_EQ(bottleneck_distance({{0, 1}}, {{0.1, 1.05}}), 0.1);
}

// The sort-free diagram of a graph whose nodes are ascending (tree_pairs' path) gives the same
// pairs, in the same order, as the general one: random multigraphs (parallel edges, several
// components, ties in the values), random edge order; on one thread or two (a sweep each).
TEST(Persistence, TheAscendingDiagramIsTheGeneralOne) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 2 + static_cast<int>(rng() % 60);
    std::vector<double> values(n);
    for (double &v : values)
      v = static_cast<double>(rng() % 12); // ties
    std::sort(values.begin(), values.end());
    std::vector<std::array<int64_t, 2>> edges;
    const int m = static_cast<int>(rng() % (2 * n));
    for (int k = 0; k < m; ++k) {
      const int64_t a = rng() % n, b = rng() % n;
      if (a != b)
        edges.push_back({std::min(a, b), std::max(a, b)});
      if (a != b && rng() % 5 == 0)
        edges.push_back({std::min(a, b), std::max(a, b)}); // a parallel edge
    }
    std::vector<GraphEdge> ge;
    for (const auto &e : edges)
      ge.push_back({e[0], e[1]});
    const auto general = persistence_diagram(ScalarGraph(values, ge)).pairs;
    for (const int threads : {1, 2}) {
      const auto sorted = persistence_diagram_ascending(values, edges, threads).pairs;
      ASSERT_EQ(general.size(), sorted.size()) << trial;
      for (std::size_t i = 0; i < general.size(); ++i) {
        EXPECT_EQ(general[i].kind, sorted[i].kind) << trial << " threads " << threads;
        EXPECT_EQ(general[i].birth, sorted[i].birth) << trial;
        EXPECT_EQ(general[i].death, sorted[i].death) << trial;
        EXPECT_EQ(general[i].birth_value, sorted[i].birth_value) << trial;
        EXPECT_EQ(general[i].death_value, sorted[i].death_value) << trial;
      }
    }
  }
}

} // namespace
} // namespace hoct
