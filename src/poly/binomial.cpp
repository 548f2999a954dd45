#include "poly/binomial.hpp"

#include <array>

namespace hoct {
namespace {

constexpr int kMaxN = 61;

struct Table {
  std::array<std::array<double, kMaxN>, kMaxN> c{};
  Table() {
    for (int n = 0; n < kMaxN; ++n) {
      c[n][0] = c[n][n] = 1.0;
      for (int k = 1; k < n; ++k)
        c[n][k] = c[n - 1][k - 1] + c[n - 1][k];
    }
  }
};

const Table &table() {
  static const Table t;
  return t;
}

} // namespace

double binomial(int n, int k) {
  if (n < 0 || k < 0 || k > n || n >= kMaxN)
    return 0.0;
  return table().c[n][k];
}

double trinomial(int i, int j, int k) { return binomial(i + j + k, i) * binomial(j + k, j); }

} // namespace hoct
