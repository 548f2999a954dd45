// Maps the integer tags a file gives its nodes or elements (positive, arbitrary, possibly
// sparse) to dense indices 0, 1, 2, ...: a flat table for compact tags (the usual 1..N costs one
// array access), a hash map for tags beyond what the caller allows the table to cover.
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace hoct {

class TagIndex {
public:
  static constexpr int64_t none = -1;

  // Lets the flat table cover tags below `limit` (it grows lazily, never beyond the largest limit
  // given). Callers derive the limit from counts already checked against the file size, so a
  // hostile tag cannot make the table large.
  void allow_flat(uint64_t limit) { flat_limit_ = std::max(flat_limit_, limit); }

  int64_t find(uint64_t tag) const {
    if (tag < flat_.size() && flat_[tag] != none)
      return flat_[tag];
    if (hashed_.empty())
      return none;
    const auto it = hashed_.find(tag);
    return it == hashed_.end() ? none : it->second;
  }

  // Maps `tag` to `index` unless it is mapped already; returns the earlier index, or none.
  int64_t insert(uint64_t tag, int64_t index) {
    const int64_t earlier = find(tag);
    if (earlier != none)
      return earlier;
    if (tag < flat_limit_) {
      if (tag >= flat_.size())
        flat_.resize(std::min(flat_limit_, std::max<uint64_t>(tag + 1, 2 * flat_.size())), none);
      flat_[tag] = index;
    } else {
      hashed_.emplace(tag, index);
    }
    return none;
  }

private:
  std::vector<int64_t> flat_;
  uint64_t flat_limit_ = 0;
  std::unordered_map<uint64_t, int64_t> hashed_;
};

} // namespace hoct
