#include "exact/seam_gluing.hpp"

#include <algorithm>
#include <stdexcept>

namespace hoct {
namespace {

// The chain of edge e of the cut mesh from its lower to its higher vertex: graph node ids.
void chain(const Topology &t, const EdgeNodes &en, int64_t e, std::vector<int64_t> &out) {
  const int64_t edge_base = t.num_vertices();
  out.assign(1, t.edge_vertices(e)[0]);
  for (int64_t i = en.offset[e]; i < en.offset[e + 1]; ++i)
    out.push_back(edge_base + i);
  out.push_back(t.edge_vertices(e)[1]);
}

} // namespace

std::vector<uint8_t> seam_nodes(const CutSurface &cut, const EdgeNodes &en, int64_t nodes) {
  std::vector<uint8_t> keep(static_cast<std::size_t>(nodes), 0);
  const Topology &t = cut.mesh.topology;
  std::vector<int64_t> c;
  for (const auto &seam : cut.seams)
    for (int64_t e : seam) {
      chain(t, en, e, c);
      for (int64_t id : c)
        keep[id] = 1;
    }
  return keep;
}

PathGluing seam_gluing(const CutSurface &cut, const EdgeNodes &en, std::span<const double> values,
                       std::span<const std::tuple<int64_t, double, int64_t>> lattice) {
  PathGluing g;
  g.group_offset = cut.group_offset;
  g.group_members = cut.copies;
  const auto on_edge = [&](int64_t e) {
    const auto first = std::lower_bound(lattice.begin(), lattice.end(), e,
                                        [](const std::tuple<int64_t, double, int64_t> &x,
                                           int64_t y) { return std::get<0>(x) < y; });
    auto last = first;
    while (last != lattice.end() && std::get<0>(*last) == e)
      ++last;
    return std::span(first, last);
  };
  for (const auto &seam : cut.seams)
    for (const auto &[e, t, id] : on_edge(seam[0]))
      for (const auto &[e2, t2, id2] : on_edge(seam[1]))
        if (t2 == t) {
          g.group_members.insert(g.group_members.end(), {id, id2});
          g.group_offset.push_back(static_cast<int64_t>(g.group_members.size()));
        }
  const Topology &t = cut.mesh.topology;
  std::vector<int64_t> a, b;
  for (const auto &seam : cut.seams) {
    chain(t, en, seam[0], a);
    chain(t, en, seam[1], b);
    if (a.size() != b.size())
      throw std::logic_error("seam_gluing: the two copies of a seam have different edge nodes");
    for (std::size_t k = 0; k + 1 < a.size(); ++k) {
      // Each piece rises in the total order (value, then id), as the tree's path between its
      // ends does (on a plateau the values alone tie).
      if (values[a[k]] < values[a[k + 1]] || (values[a[k]] == values[a[k + 1]] && a[k] < a[k + 1]))
        g.paths.push_back({a[k], a[k + 1], b[k], b[k + 1]});
      else
        g.paths.push_back({a[k + 1], a[k], b[k + 1], b[k]});
    }
  }
  return g;
}

void count_copies_once(const CutSurface &cut, const EdgeNodes &en, ExactCounts &counts) {
  const int64_t groups = static_cast<int64_t>(cut.group_offset.size()) - 1;
  int64_t seam_edge_nodes = 0;
  for (const auto &seam : cut.seams)
    seam_edge_nodes += en.count(seam[1]);
  counts.graph_nodes -= static_cast<int64_t>(cut.copies.size()) - groups + seam_edge_nodes;
  counts.edge_critical_points -= seam_edge_nodes;
}

std::vector<std::array<int64_t, 2>> seam_links(const PathGluing &g) {
  std::vector<std::array<int64_t, 2>> links;
  for (std::size_t i = 0; i + 1 < g.group_offset.size(); ++i)
    for (int64_t k = g.group_offset[i] + 1; k < g.group_offset[i + 1]; ++k)
      links.push_back({g.group_members[k - 1], g.group_members[k]});
  for (const auto &p : g.paths) {
    links.push_back({p[0], p[2]});
    links.push_back({p[1], p[3]});
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  return links;
}

} // namespace hoct
