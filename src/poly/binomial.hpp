// Binomial coefficients and multinomial weights for Bernstein bases, exact in double up to n = 60.
// Inline table lookups: they sit in the innermost loops of evaluation and subdivision.
#pragma once

#include <array>

namespace hoct {

namespace detail {

inline constexpr int kBinomialMaxN = 61;

struct BinomialTable {
  std::array<std::array<double, kBinomialMaxN>, kBinomialMaxN> c{};
  constexpr BinomialTable() {
    for (int n = 0; n < kBinomialMaxN; ++n) {
      c[n][0] = c[n][n] = 1.0;
      for (int k = 1; k < n; ++k)
        c[n][k] = c[n - 1][k - 1] + c[n - 1][k];
    }
  }
};

inline constexpr BinomialTable kBinomialTable{};

} // namespace detail

// C(n, k) as a double; 0 outside 0 <= k <= n or for n > 60.
inline double binomial(int n, int k) {
  if (n < 0 || k < 0 || k > n || n >= detail::kBinomialMaxN)
    return 0.0;
  return detail::kBinomialTable.c[n][k];
}

// Trinomial d! / (i! j! k!) for i + j + k = d.
inline double trinomial(int i, int j, int k) { return binomial(i + j + k, i) * binomial(j + k, j); }

} // namespace hoct
