#include "io/json_numbers.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

namespace hoct {

void append_json_int(std::string &out, int64_t value) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, r.ptr);
}

void append_json_double(std::string &out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  // The shortest digits that read back as `value`, as d.ddde[+-]x.
  char sci[32];
  const auto r = std::to_chars(sci, sci + sizeof sci, value, std::chars_format::scientific);
  const char *p = sci;
  if (*p == '-') {
    out += '-';
    ++p;
  }
  char digits[24];
  int k = 0; // number of digits
  const char *e = p;
  for (; e < r.ptr && *e != 'e'; ++e)
    if (*e != '.')
      digits[k++] = *e;
  int exponent = 0;
  std::from_chars(e + 1 + (e[1] == '+'), r.ptr, exponent);
  // value = 0.d1d2...dk x 10^n: n is where the decimal point goes.
  const int n = exponent + 1;
  char buf[48];
  char *q = buf;
  if (k <= n && n <= 15) { // an integer: digits, zeros, ".0"
    std::memcpy(q, digits, k);
    q += k;
    std::memset(q, '0', n - k);
    q += n - k;
    *q++ = '.';
    *q++ = '0';
  } else if (0 < n && n <= 15) { // the point inside the digits
    std::memcpy(q, digits, n);
    q += n;
    *q++ = '.';
    std::memcpy(q, digits + n, k - n);
    q += k - n;
  } else if (-4 < n && n <= 0) { // 0.000ddd
    *q++ = '0';
    *q++ = '.';
    std::memset(q, '0', -n);
    q += -n;
    std::memcpy(q, digits, k);
    q += k;
  } else { // d.ddde+XX, the exponent with two digits at least
    *q++ = digits[0];
    if (k > 1) {
      *q++ = '.';
      std::memcpy(q, digits + 1, k - 1);
      q += k - 1;
    }
    *q++ = 'e';
    const int x = n - 1;
    *q++ = x < 0 ? '-' : '+';
    const int a = x < 0 ? -x : x;
    if (a < 10)
      *q++ = '0';
    q = std::to_chars(q, buf + sizeof buf, a).ptr;
  }
  out.append(buf, q);
}

} // namespace hoct
