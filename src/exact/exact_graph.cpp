#include "exact/exact_graph.hpp"

#include "poly/reference_triangle.hpp"

#include <algorithm>

namespace hoct {

NodeSource ExactGraph::source(const Topology &topo, const EdgeNodes &en, int64_t id) const {
  if (id >= tail_base)
    return tail_source[id - tail_base];
  const bool marked = !fallback_marked.empty() && fallback_marked[static_cast<std::size_t>(id)];
  if (id < edge_base)
    return {topo.vertex_cell(id), point_on_edge(topo.vertex_corner(id), 0.0), NodeLocation::Vertex,
            marked};
  // Edge node i of edge e, placed in the edge's first cell.
  const int64_t i = id - edge_base;
  const int64_t ne = topo.num_edges();
  const int64_t e =
      std::upper_bound(en.offset.begin(), en.offset.begin() + ne + 1, i) - en.offset.begin() - 1;
  const int64_t c = topo.edge_cells_begin(e)[0];
  const int k = topo.local_edge(c, e);
  const double s = topo.edge_reversed(c, k) ? 1 - en.nodes[i].t : en.nodes[i].t;
  return {c, point_on_edge(k, s), NodeLocation::Edge, marked};
}

} // namespace hoct
