// Persistence diagrams of a scalar graph (or of a contour tree, viewed as a graph) by the elder
// rule: (minimum, join saddle) pairs from the ascending sweep, (split saddle, maximum) pairs from
// the descending sweep, and one (minimum, maximum) pair per connected component. And the
// bottleneck distance between diagrams.
#pragma once

#include "tree/scalar_graph.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

struct PersistencePair {
  // Loop: a Reeb graph's loop (tree/loop_pairs.hpp), birth its top saddle, death its bottom.
  enum class Kind : uint8_t { Join, Split, Global, Loop };
  Kind kind;
  int64_t birth, death; // graph node ids (Join: min, saddle; Split: max, saddle; Loop: top, bottom)
  double birth_value, death_value;
  double persistence() const {
    return death_value > birth_value ? death_value - birth_value : birth_value - death_value;
  }
};
const char *to_string(PersistencePair::Kind k);

struct PersistenceDiagram {
  std::vector<PersistencePair> pairs;
  // The points of one kind, as (birth_value, death_value).
  std::vector<std::array<double, 2>> points(PersistencePair::Kind kind) const;
};

PersistenceDiagram persistence_diagram(const ScalarGraph &graph);

// The same diagram (the same pairs in the same order) for a graph whose nodes 0 .. n-1 are
// already in ascending total order, as a contour tree's or Reeb graph's are: `edges` as (lower,
// upper) node pairs, in any order, parallel ones allowed. No sort: the lower and upper
// neighbours are bucketed by node. With `threads` >= 2 the join and the split sweep run on a
// thread each (the same pairs, in the same order).
PersistenceDiagram persistence_diagram_ascending(std::span<const double> values,
                                                 std::span<const std::array<int64_t, 2>> edges,
                                                 int threads = 1);

// The (birth value, death value) points of the pairs of one kind.
std::vector<std::array<double, 2>> pair_points(const std::vector<PersistencePair> &pairs,
                                               PersistencePair::Kind kind);

// Bottleneck distance (L-infinity ground metric, points may match the diagonal) between two
// point sets. Exact: binary search over the candidate values with a matching test.
double bottleneck_distance(const std::vector<std::array<double, 2>> &a,
                           const std::vector<std::array<double, 2>> &b);

} // namespace hoct
