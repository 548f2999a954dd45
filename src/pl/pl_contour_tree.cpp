#include "pl/pl_contour_tree.hpp"

#include <chrono>

namespace hoct {

TreeResult pl_contour_tree(const PlMesh &m, bool augmented, const std::string &method,
                           bool with_graph) {
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  const auto t0 = clock::now();
  const ScalarGraph g = m.graph();
  const auto t1 = clock::now();
  const MergeTree jt = join_tree(g), st = split_tree(g);
  const auto t2 = clock::now();
  const ContourTree aug = merge_trees(g, jt, st);
  const ContourTree ct = augmented ? aug : reduce(aug);
  const auto t3 = clock::now();

  TreeResult r;
  r.method = method;
  r.augmented = augmented;
  const auto types = ct.types();
  const auto deg = ct.degrees();
  r.nodes.resize(ct.size());
  for (int64_t i = 0; i < ct.size(); ++i) {
    const int64_t v = ct.nodes[i];
    TreeNode &n = r.nodes[i];
    n.type = types[i];
    n.value = ct.values[i];
    n.position = m.points[v];
    n.up = deg[i][0];
    n.down = deg[i][1];
    n.graph_node = v;
    if (v < static_cast<int64_t>(m.source_cell.size()) && m.source_cell[v] >= 0) {
      n.cell = m.source_cell[v];
      n.uv = m.source_uv[v];
      n.location = classify_location(n.uv[0], n.uv[1]);
    }
  }
  r.arcs = ct.arcs;
  if (with_graph) {
    auto graph = std::make_shared<GeometricGraph>(m.points, m.values);
    for (int64_t v = 0; v < g.size(); ++v)
      for (int64_t u : g.neighbors(v))
        if (u > v)
          graph->add_edge(v, u);
    graph->finish();
    r.graph = std::move(graph);
  }
  r.pairs = tree_pairs(ct);
  const auto t4 = clock::now();
  r.add_stat("pl_vertices", static_cast<double>(g.size()));
  r.add_stat("pl_triangles", static_cast<double>(m.triangles.size()));
  r.add_stat("pl_edges", static_cast<double>(g.num_edges()));
  r.add_stat("time_graph_s", seconds(t0, t1));
  r.add_stat("time_sweeps_s", seconds(t1, t2));
  r.add_stat("time_merge_s", seconds(t2, t3));
  r.add_stat("time_pairs_s", seconds(t3, t4));
  return r;
}

} // namespace hoct
