#include "pl/pl_cut.hpp"

#include "mesh/cut_surface.hpp"
#include "mesh/topology.hpp"
#include "util/error.hpp"

namespace hoct {

PlCut cut_pl_mesh(const PlMesh &pl, int threads) {
  MeshInput corners;
  corners.points.resize(pl.points.size());
  corners.cell_nodes.reserve(pl.triangles.size() * 3);
  for (const auto &t : pl.triangles)
    corners.add_cell(1, t.data());
  ProblemLog problems;
  const Topology topo = Topology::build(corners, problems, threads);
  corners = MeshInput{};
  if (problems.has_errors())
    throw Error("the piecewise-linear mesh is not a surface (an internal error):\n" +
                problems.summary());
  PlCut out;
  const std::vector<int64_t> cut_edges = cut_graph_edges(topo);
  if (cut_edges.empty())
    return out;
  const CornerCut cut = cut_corners(topo, cut_edges);
  const int64_t n = static_cast<int64_t>(cut.vertex_origin.size());
  out.point.resize(static_cast<std::size_t>(n));
  out.values.resize(static_cast<std::size_t>(n));
  for (int64_t v = 0; v < n; ++v) {
    out.point[v] = topo.vertex_point(cut.vertex_origin[v]);
    out.values[v] = pl.values[out.point[v]];
  }
  out.triangles.resize(pl.triangles.size());
  for (std::size_t c = 0; c < pl.triangles.size(); ++c)
    for (int k = 0; k < 3; ++k)
      out.triangles[c][k] = cut.first[topo.cell_vertices(static_cast<int64_t>(c))[k]];
  for (const auto &[corner, v] : cut.split_corners)
    out.triangles[corner / 3][corner % 3] = v;
  // The seams: each copy of a cut edge is one PL edge, monotone, from its lower end up (the
  // copies keep the originals' id order, so both copies agree on which end is lower).
  out.keep.assign(static_cast<std::size_t>(n), 0);
  out.gluing.group_offset = cut.group_offset;
  out.gluing.group_members = cut.copies;
  for (const auto &s : seam_vertices(topo, cut, cut_edges)) {
    for (int64_t v : s)
      out.keep[v] = 1;
    const bool up = out.values[s[0]] < out.values[s[1]] ||
                    (out.values[s[0]] == out.values[s[1]] && s[0] < s[1]);
    out.gluing.paths.push_back(up ? std::array<int64_t, 4>{s[0], s[1], s[2], s[3]}
                                  : std::array<int64_t, 4>{s[1], s[0], s[3], s[2]});
  }
  out.seam_edges = static_cast<int64_t>(cut_edges.size());
  return out;
}

} // namespace hoct
