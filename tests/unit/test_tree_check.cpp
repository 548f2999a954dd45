// The invariant checker (analysis/tree_check.hpp): it passes on the exact trees of every generated
// dataset and of random fields, and fails on each kind of deliberately corrupted tree.
#include "analysis/tree_check.hpp"
#include "datasets/datasets.hpp"
#include "exact/exact_contour_tree.hpp"
#include "mesh/mesh.hpp"
#include "test_meshes.hpp"
#include "util/error.hpp"

#include "io/tree_json.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace hoct {
namespace {

bool has_failure(const TreeCheckReport &r, const std::string &check) {
  for (const auto &f : r.failures)
    if (f.check == check)
      return true;
  return false;
}

TreeResult reduced_tree(const Mesh &m) { return contract_flat(exact_contour_tree(m)); }

Mesh random_mesh(int n, int degree, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(n, rng, verts, tris);
  return build_mesh(testing::lagrange_mesh(
      verts, tris, [&](int64_t) { return degree; }, {}, {}, rng));
}

TEST(TreeCheck, PassesOnEveryDataset) {
  for (const auto &name : dataset_names()) {
    SCOPED_TRACE(name);
    DatasetOptions o;
    if (name == "random")
      o.cells = 800;
    const Mesh m = build_mesh(generate_dataset(name, o));
    const TreeResult t = reduced_tree(m);
    const TreeCheckReport r = check_tree(t, m);
    EXPECT_TRUE(r.ok()) << r.summary();
    // Most nodes outside degenerate (fallback) cells are confirmed by the samples.
    int64_t exact_nodes = 0;
    for (const auto &n : t.nodes)
      exact_nodes += !n.fallback;
    EXPECT_GT(r.nodes_checked, exact_nodes / 2) << r.summary();
    std::printf("%s: %lld extrema decided from the edge polynomials, all in the tree\n",
                name.c_str(), static_cast<long long>(r.extrema_confirmed));
    // The augmented tree too (regular nodes: one arc up, one down, one sector each).
    ExactTreeOptions ao;
    ao.augmented = true;
    const TreeResult ta = exact_contour_tree(m, ao);
    const TreeCheckReport ra = check_tree(ta, m);
    EXPECT_TRUE(ra.ok()) << ra.summary();
  }
}

TEST(TreeCheck, PassesOnRandomFields) {
  for (int degree = 1; degree <= 5; ++degree)
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      SCOPED_TRACE("degree " + std::to_string(degree) + " seed " + std::to_string(seed));
      const Mesh m = random_mesh(4, degree, 100 * degree + seed);
      const TreeResult t = reduced_tree(m);
      const TreeCheckReport r = check_tree(t, m);
      EXPECT_TRUE(r.ok()) << r.summary();
      EXPECT_GT(r.nodes_checked, 0);
    }
}

class Corrupted : public ::testing::Test {
protected:
  void SetUp() override {
    mesh = build_mesh(generate_dataset("gauss", {}));
    tree = reduced_tree(mesh);
    ASSERT_TRUE(check_tree(tree, mesh).ok());
    ASSERT_GT(tree.nodes.size(), 6u);
  }
  int64_t first_of(NodeType type) const {
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
      if (tree.nodes[i].type == type && !tree.nodes[i].fallback)
        return static_cast<int64_t>(i);
    return -1;
  }
  Mesh mesh;
  TreeResult tree;
};

TEST_F(Corrupted, SwappedValues) {
  TreeResult t = tree;
  std::swap(t.nodes[1].value, t.nodes[t.nodes.size() - 2].value);
  const auto r = check_tree(t, mesh);
  EXPECT_TRUE(has_failure(r, "order")) << r.summary();
  EXPECT_TRUE(has_failure(r, "value")) << r.summary();
}

TEST_F(Corrupted, DeletedArc) {
  TreeResult t = tree;
  t.arcs.erase(t.arcs.begin() + t.arcs.size() / 2);
  for (auto &n : t.nodes)
    n.up = n.down = 0;
  const auto r = check_tree(t, mesh);
  EXPECT_TRUE(has_failure(r, "tree")) << r.summary();
  EXPECT_TRUE(has_failure(r, "euler")) << r.summary();
}

TEST_F(Corrupted, ExtraCycle) {
  TreeResult t = tree;
  // An arc between the lowest and the highest node closes a cycle.
  t.arcs.push_back({0, static_cast<int64_t>(t.nodes.size()) - 1});
  for (auto &n : t.nodes)
    n.up = n.down = 0;
  const auto r = check_tree(t, mesh);
  EXPECT_TRUE(has_failure(r, "tree")) << r.summary();
  bool cycle = false;
  for (const auto &f : r.failures)
    cycle |= f.message.find("closes a cycle") != std::string::npos;
  EXPECT_TRUE(cycle) << r.summary();
}

TEST_F(Corrupted, WrongType) {
  TreeResult t = tree;
  const int64_t s = first_of(NodeType::Saddle);
  ASSERT_GE(s, 0);
  t.nodes[s].type = NodeType::Maximum;
  const auto r = check_tree(t, mesh);
  EXPECT_TRUE(has_failure(r, "degree")) << r.summary();
  EXPECT_TRUE(has_failure(r, "type")) << r.summary();
}

TEST_F(Corrupted, MovedPosition) {
  TreeResult t = tree;
  const int64_t i = first_of(NodeType::Maximum);
  ASSERT_GE(i, 0);
  t.nodes[i].position[0] += 1e-3 * mesh.geometry.extent();
  const auto r = check_tree(t, mesh);
  EXPECT_TRUE(has_failure(r, "position")) << r.summary();
}

// A node moved to a regular point of its cell, with the value and position of the new point:
// only the samples around it can tell.
TEST_F(Corrupted, MovedToRegularPoint) {
  TreeResult t = tree;
  const int64_t i = first_of(NodeType::Maximum);
  ASSERT_GE(i, 0);
  TreeNode &n = t.nodes[i];
  // A twentieth of the way to the cell's centroid: a regular point.
  n.uv = {n.uv[0] + (1.0 / 3 - n.uv[0]) / 20, n.uv[1] + (1.0 / 3 - n.uv[1]) / 20};
  n.location = NodeLocation::Interior;
  n.value = mesh.field.value(n.cell, n.uv[0], n.uv[1]);
  n.position = mesh.geometry.position(n.cell, n.uv[0], n.uv[1]);
  const auto r = check_tree(t, mesh);
  EXPECT_FALSE(has_failure(r, "value")) << r.summary();
  EXPECT_TRUE(has_failure(r, "type")) << r.summary();
  EXPECT_TRUE(has_failure(r, "critical")) << r.summary();
  // Without the samples, the gradient there still tells.
  TreeCheckOptions no_samples;
  no_samples.check_types = false;
  const auto g = check_tree(t, mesh, no_samples);
  EXPECT_TRUE(has_failure(g, "critical")) << g.summary();
}

// An edge node moved along its edge (value and position updated): not critical on the edge.
TEST_F(Corrupted, EdgeNodeMovedAlongItsEdge) {
  TreeResult t = tree;
  int64_t i = -1;
  for (std::size_t k = 0; k < t.nodes.size() && i < 0; ++k)
    if (t.nodes[k].location == NodeLocation::Edge && !t.nodes[k].fallback &&
        std::abs(t.nodes[k].uv[1]) < 1e-12 && t.nodes[k].uv[0] > 0.1 && t.nodes[k].uv[0] < 0.9)
      i = static_cast<int64_t>(k);
  ASSERT_GE(i, 0) << "no node on a cell's edge 0";
  TreeNode &n = t.nodes[i];
  n.uv[0] += n.uv[0] < 0.5 ? 0.05 : -0.05;
  n.value = mesh.field.value(n.cell, n.uv[0], n.uv[1]);
  n.position = mesh.geometry.position(n.cell, n.uv[0], n.uv[1]);
  TreeCheckOptions no_samples;
  no_samples.check_types = false;
  no_samples.check_completeness = false;
  const auto r = check_tree(t, mesh, no_samples);
  EXPECT_TRUE(has_failure(r, "critical")) << r.summary();
}

// The extrema at vertices and on edges that the edge polynomials decide: a tree without one of
// them fails, and so do an empty tree and the min + max tree of a field with many extrema.
class Incomplete : public ::testing::Test {
protected:
  void SetUp() override {
    DatasetOptions o;
    o.cells = 800;
    mesh = build_mesh(generate_dataset("random", o));
    tree = reduced_tree(mesh);
    const TreeCheckReport r = check_tree(tree, mesh);
    ASSERT_TRUE(r.ok()) << r.summary();
    ASSERT_GT(r.extrema_confirmed, 2);
  }
  Mesh mesh;
  TreeResult tree;
};

TEST_F(Incomplete, EmptyTree) {
  TreeResult t = tree;
  t.nodes.clear();
  t.arcs.clear();
  t.pairs.clear();
  const auto r = check_tree(t, mesh);
  EXPECT_TRUE(has_failure(r, "tree")) << r.summary();
  EXPECT_TRUE(has_failure(r, "completeness")) << r.summary();
}

TEST_F(Incomplete, MinimumAndMaximumOnly) {
  TreeResult t;
  t.method = tree.method;
  t.nodes = {tree.nodes.front(), tree.nodes.back()};
  t.nodes[0].up = 1, t.nodes[0].down = 0, t.nodes[1].up = 0, t.nodes[1].down = 1;
  t.arcs = {{0, 1}};
  t.pairs = tree_pairs(as_contour_tree(t));
  const auto r = check_tree(t, mesh);
  EXPECT_FALSE(has_failure(r, "tree")) << r.summary();
  EXPECT_TRUE(has_failure(r, "completeness")) << r.summary();
}

// The tree without its first leaf (minimum or maximum, outside fallback cells) at `where`, and
// the leaf's arc; -1 if it has none.
TreeResult without_leaf(const TreeResult &tree, NodeLocation where) {
  TreeResult t = tree;
  int64_t leaf = -1;
  for (std::size_t i = 0; i < t.nodes.size() && leaf < 0; ++i)
    if ((t.nodes[i].type == NodeType::Minimum || t.nodes[i].type == NodeType::Maximum) &&
        t.nodes[i].location == where && !t.nodes[i].fallback)
      leaf = static_cast<int64_t>(i);
  if (leaf < 0)
    return {};
  t.nodes.erase(t.nodes.begin() + leaf);
  std::vector<std::array<int64_t, 2>> arcs;
  for (auto a : t.arcs) {
    if (a[0] == leaf || a[1] == leaf)
      continue;
    for (auto &x : a)
      x -= x > leaf;
    arcs.push_back(a);
  }
  t.arcs = arcs;
  for (auto &n : t.nodes)
    n.up = n.down = 0;
  t.pairs.clear();
  return t;
}

TEST_F(Incomplete, EdgeLeafRemoved) {
  const TreeResult t = without_leaf(tree, NodeLocation::Edge);
  ASSERT_FALSE(t.nodes.empty());
  const auto r = check_tree(t, mesh, {.check_types = false});
  EXPECT_TRUE(has_failure(r, "completeness")) << r.summary();
}

TEST_F(Incomplete, VertexLeafRemoved) {
  // gauss has extrema at vertices (the random field's are on edges and inside cells).
  const Mesh m = build_mesh(generate_dataset("gauss", {}));
  const TreeResult full = reduced_tree(m);
  ASSERT_TRUE(check_tree(full, m).ok());
  const TreeResult t = without_leaf(full, NodeLocation::Vertex);
  ASSERT_FALSE(t.nodes.empty());
  const auto r = check_tree(t, m, {.check_types = false});
  bool vertex = false;
  for (const auto &f : r.failures)
    vertex |= f.check == "completeness" && f.message.rfind("vertex ", 0) == 0;
  EXPECT_TRUE(vertex) << r.summary();
}

TEST_F(Incomplete, PairsNotOfTheArcs) {
  TreeResult t = tree;
  ASSERT_GT(t.pairs.size(), 2u);
  t.pairs.pop_back();
  EXPECT_TRUE(has_failure(check_tree(t, mesh), "pairs"));
  t = tree;
  std::swap(t.pairs[0].death, t.pairs[1].death);
  EXPECT_TRUE(has_failure(check_tree(t, mesh), "pairs"));
}

TEST_F(Incomplete, RecordedPersistenceMustBeTheNodes) {
  // A tree read back from its JSON passes; with one pair's persistence changed in the file, the
  // checker names the pair.
  const auto dir = std::filesystem::temp_directory_path() / "hoct-tree-check-test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "tree.json").string();
  write_tree_json(path, tree);
  const TreeResult back = read_tree_json(path);
  ASSERT_EQ(back.recorded_persistence.size(), back.pairs.size());
  EXPECT_TRUE(check_tree(back, mesh).ok()) << check_tree(back, mesh).summary();
  TreeResult t = back;
  t.recorded_persistence[1] = 2 * t.recorded_persistence[1] + 1;
  const auto r = check_tree(t, mesh);
  EXPECT_TRUE(has_failure(r, "pairs")) << r.summary();
  EXPECT_NE(r.summary().find("pair 1 records persistence"), std::string::npos) << r.summary();
  std::filesystem::remove_all(dir);
}

TEST(TreeCheck, SectorsOfAMonkeySaddle) {
  // f = x^3 - 3 x y^2 on a planar disk-like grid centred at 0: a monkey saddle at the centre
  // vertex (3 lower, 3 upper sectors) is a saddle; the checker confirms it.
  std::mt19937_64 rng(3);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(4, rng, verts, tris);
  for (auto &v : verts) {
    v[0] = 2 * v[0] - 1;
    v[1] = 2 * v[1] - 1;
  }
  verts[12] = {0, 0, 0}; // the centre of the 5 x 5 grid
  const Mesh m = build_mesh(testing::lagrange_mesh(
      verts, tris, [](int64_t) { return 3; }, {},
      [](const Vec3 &p) { return p[0] * p[0] * p[0] - 3 * p[0] * p[1] * p[1]; }, rng));
  const TreeResult t = reduced_tree(m);
  const auto r = check_tree(t, m);
  EXPECT_TRUE(r.ok()) << r.summary();
}

} // namespace
} // namespace hoct
