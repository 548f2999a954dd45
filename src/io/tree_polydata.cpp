#include "io/tree_polydata.hpp"

#include <algorithm>

namespace hoct {

TreePolyData tree_polydata(const TreeResult &t) {
  const std::size_t n = t.nodes.size(), m = t.arcs.size();
  const bool curved = t.arc_paths.size() == m && m > 0;
  // Points: the nodes first, then the interior points of the arcs' polylines.
  std::size_t extra = 0;
  if (curved)
    for (const auto &p : t.arc_paths)
      extra += p.size() > 2 ? p.size() - 2 : 0;
  const std::size_t np = n + extra;
  TreePolyData d;
  d.num_nodes = n;
  d.points.resize(3 * np);
  d.type.assign(np, NodeType::Regular);
  d.value.resize(np);
  d.persistence.assign(np, 0.0);
  d.node_id.assign(np, -1);
  d.cell.assign(np, -1);
  d.location.assign(np, NodeLocation::Unknown);
  d.fallback.assign(np, 0);
  d.node_persistence.assign(n, 0.0);
  d.arc_persistence.resize(m);
  d.line_offsets.resize(m);
  for (const auto &p : t.pairs) {
    d.node_persistence[p.birth] = std::max(d.node_persistence[p.birth], p.persistence());
    d.node_persistence[p.death] = std::max(d.node_persistence[p.death], p.persistence());
  }
  for (std::size_t i = 0; i < n; ++i) {
    const TreeNode &nd = t.nodes[i];
    std::copy(nd.position.begin(), nd.position.end(), d.points.begin() + 3 * i);
    d.type[i] = nd.type;
    d.value[i] = nd.value;
    d.persistence[i] = d.node_persistence[i];
    d.node_id[i] = static_cast<int64_t>(i);
    d.cell[i] = nd.cell;
    d.location[i] = nd.location;
    d.fallback[i] = nd.fallback ? 1 : 0;
  }
  std::size_t next = n;
  for (std::size_t a = 0; a < m; ++a) {
    const int64_t lo = t.arcs[a][0], hi = t.arcs[a][1];
    d.arc_persistence[a] = std::min(d.node_persistence[lo], d.node_persistence[hi]);
    d.line_connectivity.push_back(lo);
    if (curved) {
      // Interior points of the polyline; values interpolated along it (for colouring).
      const auto &p = t.arc_paths[a];
      for (std::size_t k = 1; k + 1 < p.size(); ++k) {
        std::copy(p[k].begin(), p[k].end(), d.points.begin() + 3 * next);
        const double f = static_cast<double>(k) / static_cast<double>(p.size() - 1);
        d.value[next] = t.nodes[lo].value + f * (t.nodes[hi].value - t.nodes[lo].value);
        d.persistence[next] = d.arc_persistence[a];
        d.line_connectivity.push_back(static_cast<int64_t>(next++));
      }
    }
    d.line_connectivity.push_back(hi);
    d.line_offsets[a] = static_cast<int64_t>(d.line_connectivity.size());
  }
  return d;
}

} // namespace hoct
