#include "tree/flat_regions.hpp"

#include "tree/union_find.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hoct {

namespace {

// No arc is flat, the arcs are sorted with the lower node first and no node is regular: the
// contraction would give the tree back as it is.
bool nothing_to_contract(const ContourTree &in, double tolerance) {
  if (!std::is_sorted(in.arcs.begin(), in.arcs.end()))
    return false;
  for (const auto &a : in.arcs)
    if (a[0] >= a[1] || std::abs(in.values[a[1]] - in.values[a[0]]) <= tolerance)
      return false;
  for (const auto &d : in.degrees())
    if (d[0] == 1 && d[1] == 1)
      return false;
  return true;
}

} // namespace

FlatContraction contract_flat_arcs(const ContourTree &in, double tolerance) {
  const int64_t n = in.size();
  if (nothing_to_contract(in, tolerance)) {
    FlatContraction out;
    out.tree = in;
    out.kept.resize(static_cast<std::size_t>(n));
    std::iota(out.kept.begin(), out.kept.end(), int64_t{0});
    out.size.assign(static_cast<std::size_t>(n), 1);
    return out;
  }
  UnionFind uf(static_cast<std::size_t>(n));
  for (const auto &a : in.arcs)
    if (std::abs(in.values[a[1]] - in.values[a[0]]) <= tolerance)
      uf.unite(a[0], a[1]);
  // Representative of a flat region: its lowest node (they share the value; the lowest id keeps
  // the total order among the survivors).
  std::vector<int64_t> rep(n, -1), region_size(n, 0);
  for (int64_t v = 0; v < n; ++v) {
    const int64_t r = uf.find(v);
    if (rep[r] < 0)
      rep[r] = v; // nodes are visited in ascending order
    ++region_size[r];
  }
  ContourTree contracted;
  std::vector<int64_t> index(n, -1), kept;
  for (int64_t v = 0; v < n; ++v)
    if (rep[uf.find(v)] == v) {
      index[v] = contracted.size();
      contracted.nodes.push_back(in.nodes[v]);
      contracted.values.push_back(in.values[v]);
      kept.push_back(v);
    }
  for (const auto &a : in.arcs) {
    const int64_t x = index[rep[uf.find(a[0])]], y = index[rep[uf.find(a[1])]];
    if (x != y)
      contracted.arcs.push_back({std::min(x, y), std::max(x, y)});
  }
  std::sort(contracted.arcs.begin(), contracted.arcs.end());
  // Splice out nodes left regular; map them back to the input.
  FlatContraction out;
  const ContourTree reduced = reduce(contracted);
  out.tree = reduced;
  // reduce() keeps node ids: find each reduced node's index in `contracted`.
  for (std::size_t i = 0, j = 0; i < reduced.nodes.size(); ++i) {
    while (contracted.nodes[j] != reduced.nodes[i])
      ++j;
    out.kept.push_back(kept[j]);
    out.size.push_back(region_size[uf.find(kept[j])]);
  }
  return out;
}

} // namespace hoct
