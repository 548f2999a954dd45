// The fingerprint of a mesh and its field (util/fingerprint.hpp), from the data themselves, not
// a file's bytes: the same mesh read from a .vtu file (raw, base64, zlib or ASCII) or a .msh file
// has the same fingerprint whenever it holds the same doubles. It covers, in this order, the
// number of points, every point's three coordinates, every node value, the number of cells,
// every cell's degree and every cell's node ids in hoct's node order (poly/lattice.hpp): a moved
// point, a changed value (to its last bit), another connectivity or another field give another
// fingerprint. The bits of the doubles are hashed as they are (0.0 and -0.0 differ). The name of
// the field is recorded beside the hash, not in it.
#pragma once

#include "mesh/mesh_input.hpp"
#include "util/fingerprint.hpp"

namespace hoct {

// One pass over the input's arrays: about 1 ns per 8-byte word on one core. An input changed
// since it was read gives the fingerprint of the data as read (MeshInput::read_fingerprint).
InputFingerprint mesh_fingerprint(const MeshInput &input);

// The same hash of an input held in consecutive parts (one per process, in order), section by
// section: a running state that each part continues and passes on (distributed/
// distributed_read). mesh_fingerprint is these steps on one part.
struct FingerprintState {
  Fingerprint64::State hash;
  uint64_t packed = 0;    // bytes of a word not yet full (degrees, kinds: eight to a word)
  uint64_t in_packed = 0; // how many
};
FingerprintState fingerprint_start();
// A section's start: its element count (points, values, cells, cell nodes).
void fingerprint_count(FingerprintState &s, uint64_t count);
// 8-byte words (doubles, ids: their bits).
void fingerprint_words(FingerprintState &s, const void *data, std::size_t words);
// Bytes eight to a word, the word's first byte lowest; the last word's rest zeros once
// fingerprint_flush_packed ends the section.
void fingerprint_packed(FingerprintState &s, const uint8_t *bytes, std::size_t n);
void fingerprint_flush_packed(FingerprintState &s);
uint64_t fingerprint_value(const FingerprintState &s);

} // namespace hoct
