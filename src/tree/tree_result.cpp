#include "tree/tree_result.hpp"

#include <cmath>

namespace hoct {

const char *to_string(NodeLocation l) {
  switch (l) {
  case NodeLocation::Vertex:
    return "vertex";
  case NodeLocation::Edge:
    return "edge";
  case NodeLocation::Interior:
    return "interior";
  case NodeLocation::Unknown:
    return "unknown";
  }
  return "?";
}

std::array<int64_t, 4> TreeResult::type_counts() const {
  std::array<int64_t, 4> c{0, 0, 0, 0};
  for (const auto &n : nodes)
    ++c[static_cast<int>(n.type)];
  return c;
}

std::vector<PersistencePair> tree_pairs(const ContourTree &tree) {
  std::vector<std::pair<int64_t, int64_t>> edges;
  edges.reserve(tree.arcs.size());
  for (const auto &a : tree.arcs)
    edges.emplace_back(a[0], a[1]);
  // Tree nodes are ascending in the total order, so their indices keep its tie-breaking.
  const ScalarGraph g(tree.values, edges);
  return persistence_diagram(g).pairs;
}

NodeLocation classify_location(double u, double v) {
  constexpr double eps = 1e-12;
  const bool on0 = std::abs(v) <= eps, on1 = std::abs(1 - u - v) <= eps, on2 = std::abs(u) <= eps;
  const int count = on0 + on1 + on2;
  if (count >= 2)
    return NodeLocation::Vertex;
  if (count == 1)
    return NodeLocation::Edge;
  return NodeLocation::Interior;
}

} // namespace hoct
