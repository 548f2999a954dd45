// io/json_numbers against nlohmann::json's own dump(), the independent truth for the text the
// tree writer produced before it formatted numbers itself: special values, integers, every
// decimal exponent from -320 to 308, and 200,000 random doubles of random magnitudes. Every
// text reads back as the same double (std::strtod and nlohmann's parser); it is nlohmann's text,
// or, where nlohmann's Grisu2 digits are not the shortest (about 0.14% of random doubles),
// shorter.
#include "io/json_numbers.hpp"
#include "io/tree_json.hpp"
#include "test_temp_dir.hpp"
#include "tree/contour_tree.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

namespace hoct {
namespace {

std::string ours(double x) {
  std::string s;
  append_json_double(s, x);
  return s;
}

// Ours reads back as x and is nlohmann's text or shorter; returns whether it is nlohmann's.
bool same_or_shorter(double x) {
  const std::string a = ours(x), b = nlohmann::json(x).dump();
  EXPECT_EQ(std::strtod(a.c_str(), nullptr), x) << a;
  EXPECT_EQ(nlohmann::json::parse(a).get<double>(), x) << a;
  EXPECT_LE(a.size(), b.size()) << a << " " << b;
  return a == b;
}

TEST(JsonNumbers, DoublesAreWrittenAsNlohmannWritesThem) {
  const double special[] = {0.0,
                            -0.0,
                            1.0,
                            -1.0,
                            0.1,
                            0.25000000000000006,
                            1e15,
                            1e16,
                            123456789012345.0,
                            1234567890123456.0,
                            1e-4,
                            1e-5,
                            0.00012345,
                            std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::min(),
                            std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::epsilon(),
                            6.234643725744338e-05,
                            100000.0,
                            1e21};
  for (double x : special)
    EXPECT_EQ(ours(x), nlohmann::json(x).dump()) << x;
  int64_t differ = 0, tried = 0;
  for (int e = -320; e <= 308; ++e)
    for (double m : {1.0, 1.5, 2.7182818284590452, 9.999999999999999}) {
      if (!std::isfinite(m * std::pow(10.0, e)))
        continue;
      differ += !same_or_shorter(m * std::pow(10.0, e));
      ++tried;
    }
  EXPECT_LE(differ, tried / 100);
  std::mt19937_64 rng(7);
  differ = 0;
  for (int i = 0; i < 200000; ++i) {
    uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x))
      continue;
    differ += !same_or_shorter(x);
  }
  EXPECT_LE(differ, 200000 / 200);
  // Not finite: null, as nlohmann writes it.
  EXPECT_EQ(ours(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(ours(-std::numeric_limits<double>::infinity()), "null");
}

TEST(JsonNumbers, IntegersAreWrittenAsNlohmannWritesThem) {
  for (int64_t x : {int64_t{0}, int64_t{-1}, int64_t{42}, std::numeric_limits<int64_t>::max(),
                    std::numeric_limits<int64_t>::min()}) {
    std::string s;
    append_json_int(s, x);
    EXPECT_EQ(s, nlohmann::json(x).dump());
  }
}

// The tree writer's arrays, long ones formatted in blocks on threads and streamed to the file:
// the same text for 1, 2 and 3 threads, in the file as in the string, and read back as the tree.
TEST(TreeJson, TheSameTextForAnyThreadCountStreamedOrNot) {
  TreeResult t;
  t.method = "exact";
  std::mt19937_64 rng(3);
  const int64_t n = 100000; // more than the 4 blocks of 8192 lines that go to threads
  for (int64_t i = 0; i < n; ++i) {
    TreeNode node;
    node.type = i == 0 ? NodeType::Minimum : (i + 1 == n ? NodeType::Maximum : NodeType::Regular);
    node.value = static_cast<double>(i) + std::ldexp(static_cast<double>(rng() % 1000), -12);
    node.position = {std::ldexp(static_cast<double>(rng()), -64), 1.5, -0.0};
    node.cell = static_cast<int64_t>(rng() % 1000);
    node.location = NodeLocation::Interior;
    node.merged = i % 7 == 0 ? 3 : 1;
    t.nodes.push_back(node);
    if (i > 0)
      t.arcs.push_back({i - 1, i});
  }
  t.pairs.push_back(
      {PersistencePair::Kind::Global, 0, n - 1, t.nodes.front().value, t.nodes.back().value});
  t.branches.push_back({n - 1, 0, t.nodes.back().value - t.nodes.front().value, -1, 0});
  const std::string one = tree_to_json(t, false, 1);
  EXPECT_EQ(tree_to_json(t, false, 2), one);
  EXPECT_EQ(tree_to_json(t, false, 3), one);
  EXPECT_EQ(nlohmann::json::parse(one)["nodes"].size(), static_cast<std::size_t>(n));
  testing::TempDir dir("hoct-json");
  const std::string path = dir.file("t.json");
  write_tree_json(path, t, false, 2);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), one + "\n");
  const TreeResult back = read_tree_json(path);
  ASSERT_EQ(back.nodes.size(), t.nodes.size());
  for (int64_t i = 0; i < n; i += 997) {
    EXPECT_EQ(back.nodes[i].value, t.nodes[i].value);
    EXPECT_EQ(back.nodes[i].position[0], t.nodes[i].position[0]);
    EXPECT_EQ(back.nodes[i].merged, t.nodes[i].merged);
  }
}

} // namespace
} // namespace hoct
