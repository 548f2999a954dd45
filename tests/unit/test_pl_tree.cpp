// The PL contour tree of a fine exact refinement against an analytic field with known critical
// points, and the JSON output contract (round trip, errors).
#include "io/tree_json.hpp"
#include "mesh/mesh.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/refinement.hpp"
#include "test_functions.hpp"
#include "test_meshes.hpp"
#include "util/error.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace hoct {
namespace {

// f = x'y'z' in a rotated frame p' = R p on the unit sphere: maxima at R^T (s1,s2,s3)/sqrt(3)
// with s1 s2 s3 = +1, minima with -1, saddles at R^T (+-e_i). 4 + 4 + 6 critical points.
struct RotatedXyz : testing::Rotation {
  Vec3 rotate(const Vec3 &p) const { return apply(p); }
  Vec3 unrotate(const Vec3 &q) const { return inverse(q); }
  double operator()(const Vec3 &p) const {
    const Vec3 q = apply(p);
    return q[0] * q[1] * q[2];
  }
};

double dist(const Vec3 &a, const Vec3 &b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(PlTree, FineRefinementFindsTheKnownCriticalPointsOfXyzOnTheSphere) {
  const RotatedXyz f;
  std::mt19937_64 rng(3);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::octahedron(6, v, t);
  const MeshInput in = testing::lagrange_mesh(
      v, t, [](int64_t) { return 4; }, testing::sphere_projection, f, rng);
  const Mesh mesh = build_mesh(in);
  const PlMesh pl = refine(mesh, 4);
  const TreeResult tree = pl_contour_tree(pl, false, "refine k=4");
  const auto counts = tree.type_counts();
  EXPECT_EQ(counts[0], 4);
  EXPECT_EQ(counts[1], 4);
  EXPECT_EQ(counts[2], 6);
  EXPECT_EQ(tree.arcs.size(), tree.nodes.size() - 1);
  // Each found node is within the refinement's resolution of a true critical point of its type.
  std::vector<std::pair<Vec3, NodeType>> truth;
  const double s = 1 / std::sqrt(3.0);
  for (int i = 0; i < 8; ++i) {
    const Vec3 q = {i & 1 ? s : -s, i & 2 ? s : -s, i & 4 ? s : -s};
    truth.push_back(
        {f.unrotate(q), q[0] * q[1] * q[2] > 0 ? NodeType::Maximum : NodeType::Minimum});
  }
  for (int i = 0; i < 3; ++i)
    for (double sign : {-1.0, 1.0}) {
      Vec3 q{0, 0, 0};
      q[i] = sign;
      truth.push_back({f.unrotate(q), NodeType::Saddle});
    }
  const double h = 1.0 / (6 * 4); // about one sub-triangle edge on the sphere
  std::vector<int> matched(truth.size(), 0);
  for (const auto &n : tree.nodes) {
    int best = -1;
    for (std::size_t i = 0; i < truth.size(); ++i)
      if (truth[i].second == n.type &&
          (best < 0 || dist(n.position, truth[i].first) < dist(n.position, truth[best].first)))
        best = static_cast<int>(i);
    ASSERT_GE(best, 0);
    EXPECT_LT(dist(n.position, truth[best].first), 3 * h) << to_string(n.type);
    EXPECT_NEAR(n.value, f(n.position), 1e-12);
    ++matched[best];
  }
  for (int m : matched)
    EXPECT_EQ(m, 1);
}

TEST(TreeJson, RoundTripAndErrors) {
  const RotatedXyz f;
  std::mt19937_64 rng(4);
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::octahedron(2, v, t);
  const Mesh mesh = build_mesh(testing::lagrange_mesh(
      v, t, [](int64_t) { return 2; }, testing::sphere_projection, f, rng));
  TreeResult tree = pl_contour_tree(refine(mesh, 2), false, "refine k=2");
  ASSERT_TRUE(mesh.fingerprint);
  tree.input = mesh.fingerprint;
  const auto dir = std::filesystem::temp_directory_path() / "hoct_tree_json_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "t.json").string();
  write_tree_json(path, tree);
  const TreeResult back = read_tree_json(path);
  ASSERT_EQ(back.nodes.size(), tree.nodes.size());
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    EXPECT_EQ(back.nodes[i].value, tree.nodes[i].value);
    EXPECT_EQ(back.nodes[i].type, tree.nodes[i].type);
    EXPECT_EQ(back.nodes[i].position, tree.nodes[i].position);
    EXPECT_EQ(back.nodes[i].location, tree.nodes[i].location);
  }
  EXPECT_EQ(back.arcs, tree.arcs);
  ASSERT_TRUE(back.input);
  EXPECT_TRUE(back.input->same_data(*mesh.fingerprint));
  EXPECT_EQ(back.input->field, mesh.field_name);
  tree.input.reset(); // a file of an earlier version: no "input"
  write_tree_json(path, tree);
  EXPECT_FALSE(read_tree_json(path).input);
  ASSERT_EQ(back.pairs.size(), tree.pairs.size());
  for (std::size_t i = 0; i < tree.pairs.size(); ++i)
    EXPECT_EQ(back.pairs[i].persistence(), tree.pairs[i].persistence());

  auto expect_error = [&](const std::string &content, const std::string &phrase) {
    const std::string bad = (dir / "bad.json").string();
    std::ofstream(bad) << content;
    try {
      read_tree_json(bad);
      ADD_FAILURE() << "accepted: " << content;
    } catch (const InputError &e) {
      EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
    }
  };
  expect_error("{", "not valid JSON");
  expect_error("{\"nodes\": []}", "not a hoct contour-tree file");
  expect_error(R"({"format":"hoct-contour-tree","nodes":[{"id":0,"type":"minimum","value":1,
      "position":[0,0,0]}],"arcs":[[0,5]],"pairs":[]})",
               "refers to node 5");
  expect_error(R"({"format":"hoct-contour-tree","nodes":[{"id":0,"type":"peak","value":1,
      "position":[0,0,0]}],"arcs":[],"pairs":[]})",
               "unknown node type");
  expect_error(R"({"format":"hoct-contour-tree","input":{"points":3,"cells":1,"field":"f",
      "fingerprint":"12345"},"nodes":[],"arcs":[],"pairs":[]})",
               "16 hexadecimal digits");
  expect_error(R"({"format":"hoct-contour-tree","input":{"cells":1,"fingerprint":"12345"},
      "nodes":[],"arcs":[],"pairs":[]})",
               "points");
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace hoct

namespace hoct {
namespace {

TEST(PlTree, DiagramsOfFinerRefinementsConverge) {
  // A smooth random field (sum of cosines) on a cubic disk mesh: the diagrams of the PL trees of
  // refinements k = 2, 4, 8 approach the one of k = 32 (the reference), monotonically.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<std::array<double, 4>> modes;
  for (int i = 0; i < 8; ++i)
    modes.push_back({6 * U(rng), 6 * U(rng), 3 * U(rng), U(rng)});
  auto f = [&](const Vec3 &p) {
    double s = 0;
    for (const auto &m : modes)
      s += m[3] * std::cos(m[0] * p[0] + m[1] * p[1] + m[2]);
    return s;
  };
  std::vector<Vec3> v;
  std::vector<std::array<int64_t, 3>> t;
  testing::square_grid(4, rng, v, t);
  const Mesh mesh = build_mesh(testing::lagrange_mesh(
      v, t, [](int64_t) { return 3; }, nullptr, f, rng));
  auto diagram = [&](int k, PersistencePair::Kind kind) {
    const TreeResult r = pl_contour_tree(refine(mesh, k), false, "");
    std::vector<std::array<double, 2>> p;
    for (const auto &x : r.pairs)
      if (x.kind == kind)
        p.push_back({x.birth_value, x.death_value});
    return p;
  };
  for (auto kind :
       {PersistencePair::Kind::Join, PersistencePair::Kind::Split, PersistencePair::Kind::Global}) {
    const auto ref = diagram(32, kind);
    double last = INFINITY;
    for (int k : {2, 4, 8}) {
      const double d = bottleneck_distance(diagram(k, kind), ref);
      EXPECT_LE(d, last) << to_string(kind) << " k=" << k;
      last = d;
    }
    EXPECT_LT(last, 0.005) << to_string(kind);
  }
}

} // namespace
} // namespace hoct
