// Replays every input the fuzz targets found (tests/data/fuzz_regressions/<target>/*) through
// the same pipeline as the target (fuzz/fuzz_harness.hpp): each must end in a clean hoct::Error
// or a mesh whose exact tree passes the invariants, with no other exception (and, under
// scripts/sanitize, no sanitizer report).
#include "fuzz_harness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using hoct::fuzz::Target;

std::string slurp(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int replay(const char *dir, Target target) {
  const fs::path root = fs::path(HOCT_TEST_DATA) / "fuzz_regressions" / dir;
  int n = 0;
  if (!fs::exists(root))
    return 0;
  for (const auto &e : fs::directory_iterator(root)) {
    SCOPED_TRACE(e.path().string());
    std::string finding;
    EXPECT_NO_THROW(finding = hoct::fuzz::run_one(target, slurp(e.path())));
    EXPECT_EQ(finding, "");
    ++n;
  }
  return n;
}

// The invariant check the targets rely on detects broken trees.
TEST(FuzzRegressions, InvariantCheckDetectsBrokenTrees) {
  hoct::TreeResult t;
  t.nodes.resize(3);
  t.nodes[0].value = 0;
  t.nodes[1].value = 1;
  t.nodes[2].value = 2;
  t.arcs = {{0, 1}, {1, 2}};
  EXPECT_EQ(hoct::fuzz::tree_invariant_violation(t), "");
  t.arcs = {{0, 1}};
  EXPECT_EQ(hoct::fuzz::tree_invariant_violation(t), "arcs != nodes - 1");
  t.arcs = {{0, 1}, {0, 1}};
  EXPECT_EQ(hoct::fuzz::tree_invariant_violation(t), "tree not connected");
  t.arcs = {{1, 0}, {1, 2}};
  EXPECT_EQ(hoct::fuzz::tree_invariant_violation(t), "arc not from the lower to the higher node");
  t.arcs = {{0, 1}, {1, 2}};
  t.nodes[1].value = std::nan("");
  EXPECT_EQ(hoct::fuzz::tree_invariant_violation(t), "arc descends in value (or a value is NaN)");
}

TEST(FuzzRegressions, Vtu) { EXPECT_GT(replay("fuzz_vtu", Target::Vtu), 0); }
TEST(FuzzRegressions, Msh41Ascii) { replay("fuzz_msh41_ascii", Target::Msh41Ascii); }
TEST(FuzzRegressions, Msh41Binary) { replay("fuzz_msh41_binary", Target::Msh41Binary); }
TEST(FuzzRegressions, Msh22) { replay("fuzz_msh22", Target::Msh22); }
TEST(FuzzRegressions, Pos) { replay("fuzz_pos", Target::Pos); }

} // namespace
