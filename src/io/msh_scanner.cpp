#include "io/msh_scanner.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <charconv>

namespace hoct {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool space(char c) { return blank(c) || c == '\n'; }

} // namespace

MshScanner::MshScanner(std::string path, std::string data)
    : path_(std::move(path)), data_(std::move(data)) {}

std::string MshScanner::where(std::size_t pos) const {
  if (byte_offsets_)
    return path_ + ": byte " + std::to_string(std::min(pos, data_.size()));
  // The line holding `pos`; at the end of the data, the last line.
  std::size_t p = std::min(pos, data_.size());
  if (p == data_.size() && p > 0 && data_[p - 1] == '\n')
    --p;
  const auto line =
      1 + std::count(data_.begin(), data_.begin() + static_cast<std::ptrdiff_t>(p), '\n');
  return path_ + ":" + std::to_string(line);
}

void MshScanner::fail_at(std::size_t pos, const std::string &what) const {
  throw InputError(where(pos) + ": " + what);
}

void MshScanner::fail_truncated(uint64_t bytes, const char *what) const {
  fail("unexpected end of file: " + std::string(what) + " needs " + std::to_string(bytes) +
       " bytes, only " + std::to_string(remaining()) + " remain");
}

void MshScanner::check_count(uint64_t count, uint64_t min_bytes, const char *what,
                             std::size_t at) const {
  if (min_bytes > 0 && count > remaining() / min_bytes)
    fail_at(at, "number of " + std::string(what) + " " + std::to_string(count) +
                    " is more than the remaining " + std::to_string(remaining()) +
                    " bytes of the file can hold (truncated file or wrong count)");
}

std::string MshScanner::quote(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < std::min(text.size(), kMax); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 32 && c < 127) {
      out += static_cast<char>(c);
    } else {
      static const char hex[] = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (text.size() > kMax)
    out += "...";
  return out + "'";
}

bool MshScanner::skip_space() {
  while (pos_ < data_.size() && space(data_[pos_]))
    ++pos_;
  return pos_ < data_.size();
}

bool MshScanner::line_ends() {
  while (pos_ < data_.size() && blank(data_[pos_]))
    ++pos_;
  return pos_ == data_.size() || data_[pos_] == '\n';
}

std::string_view MshScanner::word(const char *what) {
  if (!skip_space())
    fail(std::string("unexpected end of file: expected ") + what);
  const std::size_t start = pos_;
  while (pos_ < data_.size() && !space(data_[pos_]))
    ++pos_;
  return std::string_view(data_).substr(start, pos_ - start);
}

std::string_view MshScanner::word_on_line(const char *what) {
  if (line_ends()) {
    if (pos_ == data_.size())
      fail(std::string("unexpected end of file: expected ") + what);
    fail(std::string("the line ends where ") + what + " was expected");
  }
  const std::size_t start = pos_;
  while (pos_ < data_.size() && !space(data_[pos_]))
    ++pos_;
  return std::string_view(data_).substr(start, pos_ - start);
}

void MshScanner::end_line(const char *what) {
  if (!line_ends()) {
    const std::size_t at = pos_;
    fail_at(at, "unexpected " + quote(word("a token")) + " after " + what);
  }
  if (pos_ < data_.size())
    ++pos_;
}

std::string_view MshScanner::rest_of_line() {
  line_ends();
  const std::size_t start = pos_;
  while (pos_ < data_.size() && data_[pos_] != '\n')
    ++pos_;
  std::size_t end = pos_;
  while (end > start && blank(data_[end - 1]))
    --end;
  if (pos_ < data_.size())
    ++pos_;
  return std::string_view(data_).substr(start, end - start);
}

std::string_view MshScanner::number_token(const char *what, bool any_line, std::size_t &at) {
  const std::string_view t = any_line ? word(what) : word_on_line(what);
  at = pos_ - t.size();
  return t;
}

uint64_t MshScanner::unsigned_number(const char *what, bool any_line) {
  std::size_t at;
  const std::string_view t = number_token(what, any_line, at);
  uint64_t v;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (r.ec == std::errc::result_out_of_range)
    fail_at(at, std::string(what) + " " + quote(t) + " is out of range");
  if (r.ec != std::errc() || r.ptr != t.data() + t.size())
    fail_at(at, std::string("expected ") + what + " (a non-negative integer), got " + quote(t));
  return v;
}

int64_t MshScanner::signed_number(const char *what, bool any_line) {
  std::size_t at;
  const std::string_view t = number_token(what, any_line, at);
  int64_t v;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (r.ec == std::errc::result_out_of_range)
    fail_at(at, std::string(what) + " " + quote(t) + " is out of range");
  if (r.ec != std::errc() || r.ptr != t.data() + t.size())
    fail_at(at, std::string("expected ") + what + " (an integer), got " + quote(t));
  return v;
}

double MshScanner::real_number(const char *what, bool any_line) {
  std::size_t at;
  std::string_view t = number_token(what, any_line, at);
  // from_chars does not take a leading '+', which other writers may put.
  const std::string_view digits = t.size() > 1 && t[0] == '+' && t[1] != '-' ? t.substr(1) : t;
  double v;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (r.ec == std::errc::result_out_of_range)
    fail_at(at, std::string(what) + " " + quote(t) + " is out of the range of a double");
  if (r.ec != std::errc() || r.ptr != digits.data() + digits.size())
    fail_at(at, std::string("expected ") + what + " (a number), got " + quote(t));
  return v;
}

} // namespace hoct
