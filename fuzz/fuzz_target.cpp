// libFuzzer entry point of every reader target; fuzz/CMakeLists.txt builds it once per target
// with HOCT_FUZZ_TARGET set to the Target (fuzz_harness.hpp).
#include "fuzz_harness.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#ifndef HOCT_FUZZ_TARGET
#error "define HOCT_FUZZ_TARGET (Vtu, Msh41Ascii, Msh41Binary, Msh22 or Pos)"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, std::size_t size) {
  const std::string finding =
      hoct::fuzz::run_one(hoct::fuzz::Target::HOCT_FUZZ_TARGET,
                          std::string(reinterpret_cast<const char *>(data), size));
  if (!finding.empty()) {
    std::fprintf(stderr, "fuzz finding: %s\n", finding.c_str());
    std::abort();
  }
  return 0;
}
