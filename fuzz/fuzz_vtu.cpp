// libFuzzer target: the .vtu reader (every encoding: ascii, base64, base64+zlib, appended raw
// and base64), then the mesh checks, build_mesh and, for small meshes, the exact tree.
#include "fuzz_mesh_checks.hpp"
#include "io/vtu_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, std::size_t size) {
  hoct::MeshInput input;
  try {
    input = hoct::read_vtu_buffer(std::string(reinterpret_cast<const char *>(data), size),
                                  "fuzz.vtu", "", {.max_memory_bytes = 1ull << 30});
  } catch (const hoct::Error &) {
    return 0;
  }
  hoct::fuzz::check_mesh_input(input);
  return 0;
}
