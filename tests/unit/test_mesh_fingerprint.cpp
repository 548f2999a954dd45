// The input fingerprint (mesh/mesh_fingerprint.hpp): the same for equal meshes, another one for a
// value changed in its last bit, a coordinate changed, two cells' nodes swapped, a cell's nodes
// rotated; not changed by the field's name; recorded by build_mesh (kept or consumed input).
#include "mesh/mesh.hpp"
#include "mesh/mesh_fingerprint.hpp"
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hoct {
namespace {

MeshInput grid_mesh(uint64_t seed, int degree = 2) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> verts;
  std::vector<std::array<int64_t, 3>> tris;
  testing::square_grid(6, rng, verts, tris);
  return testing::lagrange_mesh(
      verts, tris, [&](int64_t) { return degree; }, nullptr, nullptr, rng);
}

uint64_t hash_of(const MeshInput &m) { return mesh_fingerprint(m).hash; }

TEST(MeshFingerprint, EqualMeshesHaveEqualFingerprints) {
  const MeshInput a = grid_mesh(7), b = grid_mesh(7);
  const InputFingerprint fa = mesh_fingerprint(a), fb = mesh_fingerprint(b);
  EXPECT_EQ(fa.hash, fb.hash);
  EXPECT_TRUE(fa.same_data(fb));
  EXPECT_EQ(fa.points, static_cast<int64_t>(a.points.size()));
  EXPECT_EQ(fa.cells, static_cast<int64_t>(a.num_cells()));
  EXPECT_EQ(fa.field, "f");
  MeshInput copy = a;
  copy.source = "elsewhere";
  copy.field_name = "renamed"; // recorded beside the hash, not in it
  EXPECT_EQ(hash_of(copy), fa.hash);
  EXPECT_NE(hash_of(grid_mesh(8)), fa.hash); // another seed, the same sizes
  EXPECT_NE(hash_of(grid_mesh(7, 3)), fa.hash);
}

TEST(MeshFingerprint, OneValueInItsLastBit) {
  const MeshInput a = grid_mesh(3);
  const uint64_t h = hash_of(a);
  for (std::size_t i : {std::size_t{0}, a.values.size() / 2, a.values.size() - 1}) {
    MeshInput b = a;
    b.values[i] = std::nextafter(b.values[i], INFINITY);
    EXPECT_NE(hash_of(b), h) << "value " << i;
  }
  MeshInput z = a;
  z.values[1] = 0.0;
  MeshInput nz = a;
  nz.values[1] = -0.0; // the bits are hashed: -0.0 is another value
  EXPECT_NE(hash_of(z), hash_of(nz));
}

TEST(MeshFingerprint, OneCoordinate) {
  const MeshInput a = grid_mesh(3);
  const uint64_t h = hash_of(a);
  for (int k = 0; k < 3; ++k) {
    MeshInput b = a;
    b.points[5][k] = std::nextafter(b.points[5][k], -INFINITY);
    EXPECT_NE(hash_of(b), h) << "coordinate " << k;
  }
  // Two points swapped with their values: the same set of nodes, another mesh.
  MeshInput s = a;
  std::swap(s.points[2], s.points[3]);
  std::swap(s.values[2], s.values[3]);
  EXPECT_NE(hash_of(s), h);
}

TEST(MeshFingerprint, CellsSwappingNodes) {
  const MeshInput a = grid_mesh(3);
  const uint64_t h = hash_of(a);
  const int64_t n = a.cell_offsets[1] - a.cell_offsets[0];
  // Cells 0 and 1 exchange their node lists (the same cells, in another order).
  MeshInput b = a;
  std::swap_ranges(b.cell_nodes.begin(), b.cell_nodes.begin() + n, b.cell_nodes.begin() + n);
  EXPECT_NE(hash_of(b), h);
  // Two nodes of one cell exchanged (the same nodes, another connectivity).
  MeshInput c = a;
  std::swap(c.cell_nodes[0], c.cell_nodes[1]);
  EXPECT_NE(hash_of(c), h);
  // One cell's node replaced by another.
  MeshInput d = a;
  d.cell_nodes.back() = a.cell_nodes.front();
  EXPECT_NE(hash_of(d), h);
}

TEST(MeshFingerprint, RecordedByBuildMesh) {
  const MeshInput a = grid_mesh(5);
  const InputFingerprint f = mesh_fingerprint(a);
  const Mesh kept = build_mesh(a);
  ASSERT_TRUE(kept.fingerprint);
  EXPECT_TRUE(kept.fingerprint->same_data(f));
  MeshInput consumed = a;
  const Mesh m = build_mesh(std::move(consumed));
  ASSERT_TRUE(m.fingerprint);
  EXPECT_TRUE(m.fingerprint->same_data(f));
  EXPECT_EQ(m.fingerprint->field, "f");
}

TEST(Fingerprint64, WordsInBulkEqualWordsOneByOne) {
  std::mt19937_64 rng(1);
  std::vector<uint64_t> w(103);
  for (auto &x : w)
    x = rng();
  for (std::size_t split : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{50}}) {
    Fingerprint64 one, bulk;
    for (uint64_t x : w)
      one.add(x);
    bulk.add_words(w.data(), split);
    bulk.add_words(w.data() + split, w.size() - split);
    EXPECT_EQ(one.value(), bulk.value()) << "split at " << split;
  }
  Fingerprint64 a, b;
  a.add(0);
  EXPECT_NE(a.value(), b.value()); // a zero word counts
}

TEST(InputFingerprint, HexRoundTrip) {
  InputFingerprint f;
  f.hash = 0x0123456789abcdefull;
  EXPECT_EQ(f.hex(), "0123456789abcdef");
  EXPECT_EQ(InputFingerprint::parse_hex("0123456789ABCDEF"), f.hash);
  EXPECT_FALSE(InputFingerprint::parse_hex("0123456789abcde"));
  EXPECT_FALSE(InputFingerprint::parse_hex("0123456789abcdeg"));
  EXPECT_FALSE(InputFingerprint::parse_hex("-123456789abcdef"));
}

} // namespace
} // namespace hoct
