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

// One pass over the input's arrays: about 1 ns per 8-byte word on one core.
InputFingerprint mesh_fingerprint(const MeshInput &input);

} // namespace hoct
