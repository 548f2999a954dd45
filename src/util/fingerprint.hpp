// Fingerprints: a 64-bit hash of a sequence of 64-bit words (Fingerprint64), and what a result
// records of the input it was computed from (InputFingerprint: its sizes, field name and the
// hash of its data), so that a tree can be matched with its mesh later (mesh/mesh_fingerprint.hpp
// says which data of a mesh the hash covers).
//
// The hash is not cryptographic: it tells an input from another one it was not computed from (a
// mesh of another seed, another field, a moved point), not from one built to collide. Any one
// changed word changes it (every step is a bijection of the state); word order matters.
#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

namespace hoct {

class Fingerprint64 {
public:
  void add(uint64_t word) {
    uint64_t &lane = lane_[count_ & 3];
    lane = round(lane, word);
    ++count_;
  }
  // `n` consecutive 8-byte words starting at `data` (doubles, int64: their bit patterns), four
  // lanes at a time: the lanes' rounds are independent, so they run in parallel in the core.
  void add_words(const void *data, std::size_t n) {
    const auto *bytes = static_cast<const unsigned char *>(data);
    std::size_t i = 0;
    for (; i < n && (count_ & 3) != 0; ++i)
      add(word_at(bytes, i));
    const std::size_t first = i;
    uint64_t a = lane_[0], b = lane_[1], c = lane_[2], d = lane_[3];
    for (; i + 4 <= n; i += 4) {
      a = round(a, word_at(bytes, i));
      b = round(b, word_at(bytes, i + 1));
      c = round(c, word_at(bytes, i + 2));
      d = round(d, word_at(bytes, i + 3));
    }
    lane_[0] = a, lane_[1] = b, lane_[2] = c, lane_[3] = d;
    count_ += i - first;
    for (; i < n; ++i)
      add(word_at(bytes, i));
  }

  // The running state, to continue the hash elsewhere (in another process).
  struct State {
    uint64_t lane[4];
    uint64_t count;
  };
  State state() const { return {{lane_[0], lane_[1], lane_[2], lane_[3]}, count_}; }
  static Fingerprint64 resume(const State &s) {
    Fingerprint64 h;
    for (int k = 0; k < 4; ++k)
      h.lane_[k] = s.lane[k];
    h.count_ = s.count;
    return h;
  }

  uint64_t value() const {
    uint64_t h = count_ * kMulB;
    for (uint64_t lane : lane_)
      h = (h ^ avalanche(lane)) * kMulA;
    return avalanche(h);
  }

private:
  static constexpr uint64_t kMulA = 0x9e3779b97f4a7c15ull; // odd: multiplying is a bijection
  static constexpr uint64_t kMulB = 0xd6e8feb86659fd93ull;

  static uint64_t word_at(const unsigned char *bytes, std::size_t i) {
    uint64_t w;
    std::memcpy(&w, bytes + 8 * i, 8);
    return w;
  }
  static uint64_t rotl(uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }
  // For a fixed lane a bijection of the word, and for a fixed word one of the lane.
  static uint64_t round(uint64_t lane, uint64_t word) {
    return rotl(lane + word * kMulA, 27) * kMulB;
  }
  static uint64_t avalanche(uint64_t x) {
    x ^= x >> 31;
    x *= kMulA;
    x ^= x >> 29;
    x *= kMulB;
    x ^= x >> 32;
    return x;
  }

  uint64_t lane_[4] = {0x243f6a8885a308d3ull, 0x13198a2e03707344ull, 0xa4093822299f31d0ull,
                       0x082efa98ec4e6c89ull};
  uint64_t count_ = 0;
};

// What a result records of its input: enough to say which mesh it belongs to, and to tell it
// from another in a message.
struct InputFingerprint {
  int64_t points = 0, cells = 0;
  std::string field;
  uint64_t hash = 0;

  // The same data (the field's name is for messages: a converted file may rename it).
  bool same_data(const InputFingerprint &o) const {
    return points == o.points && cells == o.cells && hash == o.hash;
  }
  // The hash as 16 lowercase hexadecimal digits.
  std::string hex() const {
    static const char digits[] = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 0; i < 16; ++i)
      s[15 - i] = digits[(hash >> (4 * i)) & 15];
    return s;
  }
  // The hash of 16 hexadecimal digits (either case); nullopt for anything else.
  static std::optional<uint64_t> parse_hex(const std::string &s) {
    if (s.size() != 16)
      return std::nullopt;
    uint64_t h = 0;
    for (char ch : s) {
      int d = ch >= '0' && ch <= '9'   ? ch - '0'
              : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10
              : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10
                                       : -1;
      if (d < 0)
        return std::nullopt;
      h = (h << 4) | static_cast<uint64_t>(d);
    }
    return h;
  }
};

} // namespace hoct
