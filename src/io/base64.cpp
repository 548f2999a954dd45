#include "io/base64.hpp"

#include <array>
#include <stdexcept>

namespace hoct {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

constexpr std::array<int8_t, 256> make_table() {
  std::array<int8_t, 256> t{};
  for (auto &x : t)
    x = -1;
  for (int i = 0; i < 64; ++i)
    t[static_cast<unsigned char>(kAlphabet[i])] = static_cast<int8_t>(i);
  return t;
}
constexpr auto kTable = make_table();

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

} // namespace

std::string base64_encode(const void *data, std::size_t size) {
  const auto *p = static_cast<const uint8_t *>(data);
  std::string out;
  out.reserve(base64_length(size));
  std::size_t i = 0;
  for (; i + 3 <= size; i += 3) {
    const uint32_t v = (uint32_t{p[i]} << 16) | (uint32_t{p[i + 1]} << 8) | p[i + 2];
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (size - i == 1) {
    const uint32_t v = uint32_t{p[i]} << 16;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += "==";
  } else if (size - i == 2) {
    const uint32_t v = (uint32_t{p[i]} << 16) | (uint32_t{p[i + 1]} << 8);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::vector<uint8_t> base64_decode(std::string_view text) {
  std::vector<uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  int group[4];
  std::size_t offsets[4] = {0, 0, 0, 0};
  int n = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (is_space(c))
      continue;
    if (c == '=') {
      group[n] = -2;
    } else {
      const int v = kTable[static_cast<unsigned char>(c)];
      if (v < 0)
        throw std::invalid_argument("invalid base64 character '" + std::string(1, c) +
                                    "' at offset " + std::to_string(i));
      group[n] = v;
    }
    offsets[n] = i;
    if (++n < 4)
      continue;
    n = 0;
    // Valid groups: xxxx, xxx=, xx==.
    const int pad = (group[3] == -2) + (group[2] == -2);
    if (group[0] < 0 || group[1] < 0 || (group[2] == -2 && group[3] != -2))
      throw std::invalid_argument(
          "misplaced base64 padding at offset " +
          std::to_string(offsets[group[0] < 0 ? 0 : (group[1] < 0 ? 1 : 2)]));
    const uint32_t v = (uint32_t(group[0]) << 18) | (uint32_t(group[1]) << 12) |
                       (uint32_t(pad >= 2 ? 0 : group[2]) << 6) | uint32_t(pad >= 1 ? 0 : group[3]);
    out.push_back(static_cast<uint8_t>(v >> 16));
    if (pad < 2)
      out.push_back(static_cast<uint8_t>((v >> 8) & 255));
    if (pad < 1)
      out.push_back(static_cast<uint8_t>(v & 255));
  }
  if (n != 0)
    throw std::invalid_argument("truncated base64 data (" + std::to_string(n) +
                                " characters left over at the end)");
  return out;
}

} // namespace hoct
