// A cursor over a Gmsh .msh file held in memory: whitespace-separated ascii tokens read line by
// line, raw binary values, and errors that name the file and the place, as "file:LINE: what"
// (ascii files) or "file: byte OFFSET: what" (binary files). Reading never goes past the data;
// every failure throws hoct::InputError.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace hoct {

class MshScanner {
public:
  MshScanner(std::string path, std::string data);

  const std::string &path() const { return path_; }
  std::size_t pos() const { return pos_; }
  std::size_t remaining() const { return data_.size() - pos_; }
  std::string_view data() const { return data_; }
  void seek(std::size_t pos) { pos_ = pos; }

  // From now on, places are given as byte offsets (binary files have no meaningful lines).
  void use_byte_offsets() { byte_offsets_ = true; }

  // "file:LINE" or "file: byte OFFSET".
  std::string where(std::size_t pos) const;
  [[noreturn]] void fail_at(std::size_t pos, const std::string &what) const;
  [[noreturn]] void fail(const std::string &what) const { fail_at(pos_, what); }

  // ---- ascii ----
  // Skips whitespace including newlines; false at the end of the data.
  bool skip_space();
  // Skips blanks (not newlines); true if the line ends here (newline or end of data).
  bool line_ends();
  // The next token, on this line or a later one. `what` names what is expected, for messages.
  std::string_view word(const char *what);
  // The next token, which must be on the current line.
  std::string_view word_on_line(const char *what);
  // The rest of the line must be blank; moves past its newline.
  void end_line(const char *what);
  // The rest of the current line without surrounding blanks; moves past its newline.
  std::string_view rest_of_line();

  // Numbers: the next token (on this line, or on any line if `any_line`), parsed entirely.
  uint64_t unsigned_number(const char *what, bool any_line = false);
  int64_t signed_number(const char *what, bool any_line = false);
  double real_number(const char *what, bool any_line = false);

  // ---- binary ----
  // Fails unless `bytes` more bytes are available.
  void need(uint64_t bytes, const char *what) const {
    if (bytes > remaining())
      fail_truncated(bytes, what);
  }
  // Reads a value whose bytes were checked with need().
  template <class T> T get_unchecked() {
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  template <class T> T get(const char *what) {
    need(sizeof(T), what);
    return get_unchecked<T>();
  }
  void skip(uint64_t bytes, const char *what) {
    need(bytes, what);
    pos_ += static_cast<std::size_t>(bytes);
  }

  // Fails (at `at`) unless `count` items of at least `min_bytes` bytes each fit in the rest of
  // the file: a guard before allocating for a count read from the file.
  void check_count(uint64_t count, uint64_t min_bytes, const char *what, std::size_t at) const;

  // A token or bytes of the file, shortened and with unprintable bytes escaped, for messages.
  static std::string quote(std::string_view text);

private:
  [[noreturn]] void fail_truncated(uint64_t bytes, const char *what) const;
  std::string_view number_token(const char *what, bool any_line, std::size_t &at);

  std::string path_;
  std::string data_;
  std::size_t pos_ = 0;
  bool byte_offsets_ = false;
};

} // namespace hoct
