// libFuzzer target: the .msh reader, then the mesh checks, build_mesh and, for small meshes, the
// exact tree. Built three times (fuzz/CMakeLists.txt), once per format: an input that does not
// start with "$MeshFormat" gets the target's format section put in front, so mutations of the
// body are read as that format (4.1 ascii, 4.1 binary or 2.2 ascii).
#include "fuzz_mesh_checks.hpp"
#include "io/msh_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

#ifndef HOCT_FUZZ_MSH_FORMAT
#error "define HOCT_FUZZ_MSH_FORMAT to 41, 41 binary (411) or 22"
#endif

namespace {

std::string format_section() {
#if HOCT_FUZZ_MSH_FORMAT == 41
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
#elif HOCT_FUZZ_MSH_FORMAT == 411
  const int one = 1;
  return "$MeshFormat\n4.1 1 8\n" + std::string(reinterpret_cast<const char *>(&one), 4) +
         "\n$EndMeshFormat\n";
#else
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
#endif
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char *>(data), size);
  if (bytes.rfind("$MeshFormat", 0) != 0)
    bytes = format_section() + bytes;
  hoct::MeshInput input;
  try {
    input =
        hoct::read_msh_buffer(std::move(bytes), "fuzz.msh", "", {.max_memory_bytes = 1ull << 30});
  } catch (const hoct::Error &) {
    return 0;
  }
  hoct::fuzz::check_mesh_input(input);
  return 0;
}
