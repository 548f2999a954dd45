// libFuzzer target for the core: arbitrary small meshes and coefficients (fuzz/core/core_case.hpp)
// must give a tree that passes the invariant checker, or a hoct::Error. Anything else (a failed
// check, a crash, a sanitizer report, another exception) is a finding.
#include "core_case.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::string findings = hoct::fuzzing::run_core_case(data, size);
  if (!findings.empty()) {
    std::fprintf(stderr, "fuzz_core: the tree fails the invariant checker:\n%s", findings.c_str());
    std::abort();
  }
  return 0;
}
