// Trivially copyable values and arrays of them as bytes, for messages between processes
// (exact/piece_codec, mesh/piece_surface): a writer that appends, a reader that checks every
// length against what is left and throws std::runtime_error("<what>: ...") past the end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace hoct {

class ByteWriter {
public:
  template <class T> void value(const T &v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto *p = reinterpret_cast<const std::byte *>(&v);
    out.insert(out.end(), p, p + sizeof(T));
  }
  // Its length (uint64), then its elements.
  template <class T, class A> void array(const std::vector<T, A> &v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value<uint64_t>(v.size());
    if (v.empty())
      return;
    const auto *p = reinterpret_cast<const std::byte *>(v.data());
    out.insert(out.end(), p, p + v.size() * sizeof(T));
  }
  // Its length, then its characters.
  void text(const std::string &s) { array(std::vector<char>(s.begin(), s.end())); }
  std::vector<std::byte> out;
};

class ByteReader {
public:
  ByteReader(std::span<const std::byte> in, std::string what) : in_(in), what_(std::move(what)) {}
  template <class T> T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    take(&v, sizeof(T));
    return v;
  }
  template <class T, class A = std::allocator<T>> std::vector<T, A> array() {
    const uint64_t n = value<uint64_t>();
    if (n > (in_.size() - at_) / sizeof(T))
      throw std::runtime_error(what_ + ": an array runs past the end");
    std::vector<T, A> v(static_cast<std::size_t>(n));
    take(v.data(), v.size() * sizeof(T));
    return v;
  }
  std::string text() {
    const std::vector<char> v = array<char>();
    return std::string(v.begin(), v.end());
  }
  bool done() const { return at_ == in_.size(); }

private:
  void take(void *to, std::size_t bytes) {
    if (bytes > in_.size() - at_)
      throw std::runtime_error(what_ + ": the bytes end early");
    if (bytes == 0) // an empty array's data() may be null
      return;
    std::memcpy(to, in_.data() + at_, bytes);
    at_ += bytes;
  }
  std::span<const std::byte> in_;
  std::string what_;
  std::size_t at_ = 0;
};

} // namespace hoct
