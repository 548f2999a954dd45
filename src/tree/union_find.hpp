// Disjoint sets with path halving and union by size.
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace hoct {

class UnionFind {
public:
  explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), int64_t{0});
  }
  int64_t find(int64_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  // Returns true if x and y were in different sets.
  bool unite(int64_t x, int64_t y) {
    x = find(x);
    y = find(y);
    if (x == y)
      return false;
    if (size_[x] < size_[y])
      std::swap(x, y);
    parent_[y] = x;
    size_[x] += size_[y];
    return true;
  }

private:
  std::vector<int64_t> parent_, size_;
};

} // namespace hoct
