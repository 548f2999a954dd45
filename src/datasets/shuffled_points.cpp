#include "datasets/shuffled_points.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace hoct {

MeshInput with_points_shuffled(const MeshInput &in, uint32_t seed) {
  std::vector<int64_t> perm(in.num_points());
  std::iota(perm.begin(), perm.end(), int64_t{0});
  std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
  MeshInput out = in;
  for (std::size_t i = 0; i < perm.size(); ++i) {
    out.points[static_cast<std::size_t>(perm[i])] = in.points[i];
    out.values[static_cast<std::size_t>(perm[i])] = in.values[i];
  }
  for (int64_t &q : out.cell_nodes)
    q = perm[static_cast<std::size_t>(q)];
  return out;
}

} // namespace hoct
