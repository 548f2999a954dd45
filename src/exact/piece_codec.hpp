// PieceTrees and ReebGroup as bytes and back: what one MPI rank sends another
// (pipeline/distributed_tree). The layout is this build's own (both ends run the same binary): a
// header, then each array as its length and its elements' bytes.
#pragma once

#include "exact/piece_trees.hpp"
#include "exact/reeb_group.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

std::vector<std::byte> encode_piece_trees(const PieceTrees &trees);
// Throws std::runtime_error for bytes that are not one encoded PieceTrees.
PieceTrees decode_piece_trees(std::span<const std::byte> bytes);

std::vector<std::byte> encode_reeb_group(const ReebGroup &group);
// Throws std::runtime_error for bytes that are not one encoded ReebGroup.
ReebGroup decode_reeb_group(std::span<const std::byte> bytes);

} // namespace hoct
