#include "load_mesh.hpp"

#include "io/read_mesh.hpp"
#include "memory_guard.hpp"

#include <chrono>

namespace hoct::cli {

LoadedMesh load_mesh(const std::string &path, const std::string &scalar, bool strict) {
  using clock = std::chrono::steady_clock;
  LoadedMesh r;
  const auto t0 = clock::now();
  r.input = read_mesh(path, scalar, read_limits());
  const auto t1 = clock::now();
  r.mesh = build_mesh(r.input, {.throw_on_error = strict});
  const auto t2 = clock::now();
  r.read_seconds = std::chrono::duration<double>(t1 - t0).count();
  r.build_seconds = std::chrono::duration<double>(t2 - t1).count();
  return r;
}

} // namespace hoct::cli
