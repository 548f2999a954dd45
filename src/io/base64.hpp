// Base64 for VTK XML files. The decoder is strict and accepts what VTK writes: the concatenation
// of separately padded streams (the header and the data of an inline binary array are encoded
// separately), i.e. '=' padding at the end of any 4-character group. Whitespace is skipped; any
// other character is an error naming its offset. (Debian's libb64 skips invalid characters and
// padding silently, which misaligns such data and hides corruption.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hoct {

std::string base64_encode(const void *data, std::size_t size);

// Throws std::invalid_argument with the offset of the first bad character.
std::vector<uint8_t> base64_decode(std::string_view text);

// Number of base64 characters (excluding whitespace) that encode `bytes` bytes as one padded
// stream.
inline std::size_t base64_length(std::size_t bytes) { return 4 * ((bytes + 2) / 3); }

} // namespace hoct
