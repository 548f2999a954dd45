#include "tree/path_gluing.hpp"

#include "tree/union_find.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace hoct {
namespace {

// A level: the value, then the lowest tree index of the node's group (one level per group).
struct Level {
  double value;
  int64_t low;
  bool operator<(const Level &o) const {
    return value < o.value || (value == o.value && low < o.low);
  }
  bool operator==(const Level &o) const { return value == o.value && low == o.low; }
  bool operator<=(const Level &o) const { return !(o < *this); }
};

// Two arcs glued on the levels [lo, hi].
struct Glued {
  int64_t a, b;
  Level lo, hi;
};

// The tree rooted at each component's lowest node: parent, the arc to it, depth.
struct RootedTree {
  std::vector<int64_t> parent, parent_arc, depth;

  explicit RootedTree(const ContourTree &t) {
    const int64_t n = t.size();
    std::vector<int64_t> off(n + 1, 0), adj(2 * t.arcs.size());
    for (const auto &a : t.arcs) {
      ++off[a[0] + 1];
      ++off[a[1] + 1];
    }
    for (int64_t i = 0; i < n; ++i)
      off[i + 1] += off[i];
    std::vector<int64_t> fill(off.begin(), off.end() - 1);
    for (std::size_t k = 0; k < t.arcs.size(); ++k) {
      adj[fill[t.arcs[k][0]]++] = static_cast<int64_t>(k);
      adj[fill[t.arcs[k][1]]++] = static_cast<int64_t>(k);
    }
    parent.assign(n, -2);
    parent_arc.assign(n, -1);
    depth.assign(n, 0);
    std::vector<int64_t> queue;
    for (int64_t root = 0; root < n; ++root) {
      if (parent[root] != -2)
        continue;
      parent[root] = -1;
      queue.assign(1, root);
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const int64_t v = queue[q];
        for (int64_t k = off[v]; k < off[v + 1]; ++k) {
          const auto &a = t.arcs[adj[k]];
          const int64_t w = a[0] == v ? a[1] : a[0];
          if (parent[w] != -2)
            continue;
          parent[w] = v;
          parent_arc[w] = adj[k];
          depth[w] = depth[v] + 1;
          queue.push_back(w);
        }
      }
    }
  }

  // The path from u to w: its nodes and arcs, in order from u.
  void path(int64_t u, int64_t w, std::vector<int64_t> &nodes, std::vector<int64_t> &arcs) const {
    std::vector<int64_t> tail_nodes, tail_arcs;
    nodes.assign(1, u);
    arcs.clear();
    while (u != w) {
      if (depth[u] >= depth[w] && parent[u] >= 0) {
        arcs.push_back(parent_arc[u]);
        u = parent[u];
        nodes.push_back(u);
      } else if (parent[w] >= 0) {
        tail_arcs.push_back(parent_arc[w]);
        tail_nodes.push_back(w);
        w = parent[w];
      } else {
        throw std::invalid_argument("glue_paths: a path between two components of the tree");
      }
    }
    nodes.insert(nodes.end(), tail_nodes.rbegin(), tail_nodes.rend());
    arcs.insert(arcs.end(), tail_arcs.rbegin(), tail_arcs.rend());
  }
};

} // namespace

GluedGraph glue_paths(const ContourTree &tree, const PathGluing &gluing, bool reduced) {
  const int64_t n = tree.size();
  GluedGraph out;
  std::vector<std::pair<int64_t, int64_t>> by_id(static_cast<std::size_t>(n));
  for (int64_t i = 0; i < n; ++i)
    by_id[i] = {tree.nodes[i], i};
  std::sort(by_id.begin(), by_id.end());
  auto index = [&](int64_t id) {
    auto it = std::lower_bound(by_id.begin(), by_id.end(), std::pair<int64_t, int64_t>{id, -1});
    if (it == by_id.end() || it->first != id)
      throw std::invalid_argument("glue_paths: node " + std::to_string(id) +
                                  " is not a node of the tree");
    return it->second;
  };
  UnionFind same(static_cast<std::size_t>(n));
  for (std::size_t g = 0; g + 1 < gluing.group_offset.size(); ++g)
    for (int64_t k = gluing.group_offset[g] + 1; k < gluing.group_offset[g + 1]; ++k)
      same.unite(index(gluing.group_members[gluing.group_offset[g]]),
                 index(gluing.group_members[k]));
  std::vector<std::array<int64_t, 4>> paths;
  paths.reserve(gluing.paths.size());
  for (const auto &p : gluing.paths) {
    paths.push_back({index(p[0]), index(p[1]), index(p[2]), index(p[3])});
    same.unite(paths.back()[0], paths.back()[2]);
    same.unite(paths.back()[1], paths.back()[3]);
  }
  std::vector<int64_t> low(static_cast<std::size_t>(n), -1), low_of_root(n, -1);
  for (int64_t i = 0; i < n; ++i) {
    int64_t &l = low_of_root[same.find(i)];
    if (l < 0)
      l = i; // nodes ascend: the first one met is the lowest
    low[i] = l;
  }
  auto level = [&](int64_t i) { return Level{tree.values[i], low[i]}; };

  // The glued pairs of arcs: both paths walked upwards together, a piece per level between
  // consecutive nodes of either.
  const bool routed = !gluing.routes.empty();
  if (routed && gluing.routes.size() != gluing.paths.size())
    throw std::invalid_argument("glue_paths: one route per path, or none");
  const RootedTree rooted(routed ? ContourTree{} : tree);
  const auto follow = [&](int64_t from, int64_t to, const std::vector<int64_t> &route,
                          std::vector<int64_t> &nodes, std::vector<int64_t> &arcs) {
    nodes.assign(1, from);
    arcs = route;
    for (const int64_t a : route) {
      if (a < 0 || a >= static_cast<int64_t>(tree.arcs.size()) ||
          (tree.arcs[a][0] != nodes.back() && tree.arcs[a][1] != nodes.back()))
        throw std::invalid_argument("glue_paths: a route that does not follow its arcs");
      nodes.push_back(tree.arcs[a][0] == nodes.back() ? tree.arcs[a][1] : tree.arcs[a][0]);
    }
    if (nodes.back() != to)
      throw std::invalid_argument("glue_paths: a route that does not end at its path's end");
  };
  std::vector<Glued> glued;
  std::vector<int64_t> p, pa, q, qa;
  auto rising = [&](const std::vector<int64_t> &nodes) {
    for (std::size_t k = 1; k < nodes.size(); ++k)
      if (level(nodes[k]) < level(nodes[k - 1]))
        return false;
    return true;
  };
  for (std::size_t r = 0; r < paths.size(); ++r) {
    const auto &path = paths[r];
    if (routed) {
      follow(path[0], path[1], gluing.routes[r][0], p, pa);
      follow(path[2], path[3], gluing.routes[r][1], q, qa);
    } else {
      rooted.path(path[0], path[1], p, pa);
      rooted.path(path[2], path[3], q, qa);
    }
    if (!rising(p) || !rising(q)) {
      ++out.nonmonotone_paths;
      continue;
    }
    std::size_t i = 0, j = 0;
    Level cur = level(p[0]);
    while (i < pa.size() && j < qa.size()) {
      const Level k1 = level(p[i + 1]), k2 = level(q[j + 1]);
      const Level top = k1 < k2 ? k1 : k2;
      if (pa[i] != qa[j] && cur < top)
        glued.push_back({pa[i], qa[j], cur, top});
      cur = top;
      if (k1 == top)
        ++i;
      if (k2 == top)
        ++j;
    }
  }

  // Cut levels per arc: the glued pieces' ends inside it, spread along glued pairs until every
  // pair is cut alike.
  const int64_t m = static_cast<int64_t>(tree.arcs.size());
  std::vector<std::vector<int64_t>> touching(static_cast<std::size_t>(m));
  for (std::size_t r = 0; r < glued.size(); ++r) {
    touching[glued[r].a].push_back(static_cast<int64_t>(r));
    touching[glued[r].b].push_back(static_cast<int64_t>(r));
  }
  std::vector<std::vector<Level>> cuts(static_cast<std::size_t>(m));
  std::vector<std::pair<int64_t, Level>> work;
  auto add = [&](int64_t arc, const Level &k) {
    if (!(level(tree.arcs[arc][0]) < k && k < level(tree.arcs[arc][1])))
      return;
    auto &c = cuts[arc];
    auto it = std::lower_bound(c.begin(), c.end(), k);
    if (it != c.end() && *it == k)
      return;
    c.insert(it, k);
    work.push_back({arc, k});
  };
  for (const Glued &g : glued)
    for (int64_t arc : {g.a, g.b}) {
      add(arc, g.lo);
      add(arc, g.hi);
    }
  while (!work.empty()) {
    const auto [arc, k] = work.back();
    work.pop_back();
    for (int64_t r : touching[arc]) {
      const Glued &g = glued[r];
      if (g.lo < k && k < g.hi)
        add(g.a == arc ? g.b : g.a, k);
    }
  }

  // Points: the tree's nodes, then each arc's cut points; sub-arcs between consecutive points.
  std::vector<int64_t> cut_first(static_cast<std::size_t>(m) + 1, 0);
  for (int64_t a = 0; a < m; ++a)
    cut_first[a + 1] = cut_first[a] + static_cast<int64_t>(cuts[a].size());
  // The k-th point of arc a from its lower end (0: the lower node; cuts; the upper node), and
  // the position of level `l` among them.
  auto point = [&](int64_t a, int64_t k) {
    const int64_t c = static_cast<int64_t>(cuts[a].size());
    return k == 0 ? tree.arcs[a][0] : (k == c + 1 ? tree.arcs[a][1] : n + cut_first[a] + k - 1);
  };
  auto position = [&](int64_t a, const Level &l) -> int64_t {
    if (l == level(tree.arcs[a][0]))
      return 0;
    if (l == level(tree.arcs[a][1]))
      return static_cast<int64_t>(cuts[a].size()) + 1;
    auto it = std::lower_bound(cuts[a].begin(), cuts[a].end(), l);
    if (it == cuts[a].end() || !(*it == l))
      throw std::logic_error("glue_paths: a glued level is not a cut of its arc");
    return 1 + (it - cuts[a].begin());
  };
  auto sub_arc = [&](int64_t a, int64_t k) { return cut_first[a] + a + k; };
  UnionFind points(static_cast<std::size_t>(n + cut_first[m]));
  UnionFind subs(static_cast<std::size_t>(cut_first[m] + m));
  for (int64_t i = 0; i < n; ++i)
    points.unite(i, low[i]);
  for (const Glued &g : glued) {
    const int64_t sa = position(g.a, g.lo), ea = position(g.a, g.hi);
    const int64_t sb = position(g.b, g.lo), eb = position(g.b, g.hi);
    if (ea - sa != eb - sb)
      throw std::logic_error("glue_paths: glued arcs cut at different levels");
    for (int64_t k = 0; k <= ea - sa; ++k)
      points.unite(point(g.a, sa + k), point(g.b, sb + k));
    for (int64_t k = 0; k < ea - sa; ++k)
      subs.unite(sub_arc(g.a, sa + k), sub_arc(g.b, sb + k));
  }

  // The quotient: one node per class of points (each holds a tree node: every cut is the level
  // of one), one arc per class of sub-arcs.
  std::vector<int64_t> node_of(static_cast<std::size_t>(n + cut_first[m]), -1);
  ContourTree g;
  for (int64_t i = 0; i < n; ++i) {
    int64_t &x = node_of[points.find(i)];
    if (x < 0) {
      x = g.size();
      g.nodes.push_back(tree.nodes[i]);
      g.values.push_back(tree.values[i]);
    }
  }
  std::vector<int64_t> arc_of(static_cast<std::size_t>(cut_first[m] + m), -1);
  for (int64_t a = 0; a < m; ++a)
    for (int64_t k = 0; k <= static_cast<int64_t>(cuts[a].size()); ++k) {
      const int64_t s = subs.find(sub_arc(a, k));
      if (arc_of[s] >= 0)
        continue;
      const int64_t x = node_of[points.find(point(a, k))];
      const int64_t y = node_of[points.find(point(a, k + 1))];
      if (x < 0 || y < 0)
        throw std::logic_error("glue_paths: a cut point glued to no node");
      if (x == y) { // an arc between two nodes of one point (a tie) is no arc
        arc_of[s] = m + cut_first[m];
        continue;
      }
      arc_of[s] = static_cast<int64_t>(g.arcs.size());
      g.arcs.push_back({std::min(x, y), std::max(x, y)});
    }
  // Arcs sorted, and where each piece of an input arc went.
  const std::vector<int64_t> rank = sort_arcs(g.arcs);
  if (!reduced) {
    out.node_of.resize(static_cast<std::size_t>(n));
    for (int64_t i = 0; i < n; ++i)
      out.node_of[i] = node_of[points.find(i)];
    out.arc_image.resize(static_cast<std::size_t>(m));
    for (int64_t a = 0; a < m; ++a)
      for (int64_t k = 0; k <= static_cast<int64_t>(cuts[a].size()); ++k)
        if (const int64_t x = arc_of[subs.find(sub_arc(a, k))]; x < m + cut_first[m])
          out.arc_image[a].push_back(rank[x]);
  }
  out.graph = reduced ? reduce(g) : std::move(g);
  return out;
}

std::vector<std::vector<int64_t>> forest_paths(const ContourTree &forest,
                                               const std::vector<std::array<int64_t, 2>> &ends) {
  const RootedTree rooted(forest);
  std::vector<std::vector<int64_t>> out(ends.size());
  std::vector<int64_t> nodes;
  for (std::size_t i = 0; i < ends.size(); ++i)
    rooted.path(ends[i][0], ends[i][1], nodes, out[i]);
  return out;
}

} // namespace hoct
