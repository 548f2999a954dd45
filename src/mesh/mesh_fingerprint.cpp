#include "mesh/mesh_fingerprint.hpp"

#include <type_traits>

namespace hoct {

namespace {

// Distinguishes the fingerprint from other uses of the hash, and its layout from later ones.
constexpr uint64_t kLayoutTag = 0x686f63742d667031ull; // "hoct-fp1"

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_trivially_copyable_v<Vec3>,
              "points are hashed as consecutive doubles");

} // namespace

FingerprintState fingerprint_start() {
  Fingerprint64 h;
  h.add(kLayoutTag);
  return FingerprintState{h.state(), 0, 0};
}

void fingerprint_count(FingerprintState &s, uint64_t count) {
  Fingerprint64 h = Fingerprint64::resume(s.hash);
  h.add(count);
  s.hash = h.state();
}

void fingerprint_words(FingerprintState &s, const void *data, std::size_t words) {
  Fingerprint64 h = Fingerprint64::resume(s.hash);
  h.add_words(data, words);
  s.hash = h.state();
}

void fingerprint_packed(FingerprintState &s, const uint8_t *bytes, std::size_t n) {
  Fingerprint64 h = Fingerprint64::resume(s.hash);
  for (std::size_t i = 0; i < n; ++i) {
    s.packed |= static_cast<uint64_t>(bytes[i]) << (8 * s.in_packed);
    if (++s.in_packed == 8) {
      h.add(s.packed);
      s.packed = 0;
      s.in_packed = 0;
    }
  }
  s.hash = h.state();
}

void fingerprint_flush_packed(FingerprintState &s) {
  if (s.in_packed == 0)
    return;
  Fingerprint64 h = Fingerprint64::resume(s.hash);
  h.add(s.packed);
  s.hash = h.state();
  s.packed = 0;
  s.in_packed = 0;
}

uint64_t fingerprint_value(const FingerprintState &s) {
  return Fingerprint64::resume(s.hash).value();
}

InputFingerprint mesh_fingerprint(const MeshInput &input) {
  if (input.read_fingerprint)
    return *input.read_fingerprint;
  FingerprintState s = fingerprint_start();
  fingerprint_count(s, input.points.size());
  fingerprint_words(s, input.points.data(), 3 * input.points.size());
  fingerprint_count(s, input.values.size());
  fingerprint_words(s, input.values.data(), input.values.size());
  fingerprint_count(s, input.cell_degree.size());
  fingerprint_packed(s, input.cell_degree.data(), input.cell_degree.size());
  fingerprint_flush_packed(s);
  fingerprint_count(s, input.cell_nodes.size());
  fingerprint_words(s, input.cell_nodes.data(), input.cell_nodes.size());
  // The kinds, where any cell is not a Lagrange triangle (a mesh of those alone keeps the
  // fingerprint it always had).
  if (!input.lagrange_triangles_only()) {
    fingerprint_packed(s, input.cell_kind.data(), input.cell_kind.size());
    fingerprint_flush_packed(s);
  }
  InputFingerprint f;
  f.points = static_cast<int64_t>(input.points.size());
  f.cells = static_cast<int64_t>(input.cell_degree.size());
  f.field = input.field_name;
  f.hash = fingerprint_value(s);
  return f;
}

} // namespace hoct
