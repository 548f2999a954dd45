#include "mesh/mesh_fingerprint.hpp"

#include <type_traits>

namespace hoct {

namespace {

// Distinguishes the fingerprint from other uses of the hash, and its layout from later ones.
constexpr uint64_t kLayoutTag = 0x686f63742d667031ull; // "hoct-fp1"

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_trivially_copyable_v<Vec3>,
              "points are hashed as consecutive doubles");

} // namespace

InputFingerprint mesh_fingerprint(const MeshInput &input) {
  Fingerprint64 h;
  h.add(kLayoutTag);
  h.add(input.points.size());
  h.add_words(input.points.data(), 3 * input.points.size());
  h.add(input.values.size());
  h.add_words(input.values.data(), input.values.size());
  h.add(input.cell_degree.size());
  // The degrees eight to a word (the last word padded with zeros).
  const std::size_t nd = input.cell_degree.size();
  for (std::size_t c = 0; c < nd; c += 8) {
    uint64_t w = 0;
    for (std::size_t k = 0; k < 8 && c + k < nd; ++k)
      w |= static_cast<uint64_t>(input.cell_degree[c + k]) << (8 * k);
    h.add(w);
  }
  h.add(input.cell_nodes.size());
  h.add_words(input.cell_nodes.data(), input.cell_nodes.size());
  // The kinds, where any cell is not a Lagrange triangle (a mesh of those alone keeps the
  // fingerprint it always had).
  if (!input.lagrange_triangles_only())
    for (std::size_t c = 0; c < nd; c += 8) {
      uint64_t w = 0;
      for (std::size_t k = 0; k < 8 && c + k < nd; ++k)
        w |= static_cast<uint64_t>(input.cell_kind[c + k]) << (8 * k);
      h.add(w);
    }
  InputFingerprint f;
  f.points = static_cast<int64_t>(input.points.size());
  f.cells = static_cast<int64_t>(input.cell_degree.size());
  f.field = input.field_name;
  f.hash = h.value();
  return f;
}

} // namespace hoct
