// Inputs the core fuzz target (fuzz/core) once failed on, replayed: each must now give a tree
// that passes the invariant checker, or a clear hoct::Error.
#include "../../fuzz/core/core_case.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace hoct {
namespace {

TEST(FuzzCoreRegressions, EveryKeptInputPassesTheChecker) {
  const std::filesystem::path dir = std::filesystem::path(HOCT_TEST_DATA) / "fuzz_core";
  int replayed = 0;
  for (const auto &entry : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    SCOPED_TRACE(entry.path().filename().string());
    EXPECT_EQ(fuzzing::run_core_case(bytes.data(), bytes.size()), "");
    ++replayed;
  }
  EXPECT_GT(replayed, 0);
}

} // namespace
} // namespace hoct
