#include "exact/degenerate_cells.hpp"

#include "cell/strict_extrema.hpp"
#include "exact/cell_phase.hpp"
#include "pl/cell_refinement.hpp"
#include "poly/interpolation_error.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace hoct {

DegenerateCells refine_degenerate_cells(const Mesh &mesh, const EdgeNodes &en, int K,
                                        bool arc_geometry, ExactGraph &g) {
  const Topology &topo = mesh.topology;
  const Field &field = mesh.field;
  DegenerateCells out;
  std::map<std::pair<int64_t, int>, int64_t> lattice_node; // (edge, step from lo) -> id
  // The largest error per node id so far (-1: none).
  std::vector<double> node_bound;
  auto bound = [&](int64_t id, double error) {
    if (static_cast<std::size_t>(id) >= node_bound.size())
      node_bound.resize(
          std::max<std::size_t>(static_cast<std::size_t>(id) + 1, node_bound.size() * 3 / 2), -1.0);
    node_bound[id] = std::max(node_bound[id], error);
  };
  // Pass 1: each cell's refinement, its sub-vertices' ids where they exist already (corners,
  // edge nodes), its lattice points on edges collected. Then the lattice nodes get their ids in
  // the order of their edges and steps (the whole mesh's edge order: a piece of the mesh numbers
  // them alike, exact/piece_trees), each placed in the first cell that has it; pass 2 adds the
  // cells' interior sub-vertices and sub-edges.
  struct Prepared {
    int64_t cell;
    CellRefinement refinement;
    std::vector<int64_t> ids;       // -1: interior sub-vertex, -2 - k: the k-th of `lattice` below
    std::vector<int64_t *> lattice; // where each lattice node's id will be
  };
  std::vector<Prepared> prepared;
  struct LatticePlace {
    int64_t cell;
    double u, v;
    int64_t id = -1;
  };
  std::map<std::pair<int64_t, int>, LatticePlace> lattice_place;
  std::array<std::vector<double>, 3> extra;
  for (const int64_t c : g.fallback_cells) {
    for (int b = 0; b < kFallbackReasons; ++b)
      if (g.fallback[c] & (1u << b))
        ++out.reasons[b];
    // A constant cell is one flat region (docs/ALGORITHM.md §4): its boundary, the
    // chains of its three edges (its corners, and the lattice nodes its non-constant neighbours
    // put there), all of its value, already connects it; sub-vertices inside it would only add
    // nodes of that value.
    if (g.fallback[c] & fallback_bit(FallbackReason::ConstantCell)) {
      for (int k = 0; k < 3; ++k) {
        g.mark_fallback(topo.cell_vertices(c)[k]);
        bound(topo.cell_vertices(c)[k], 0);
        const int64_t e = topo.cell_edge(c, k);
        for (int64_t i = 0; i < en.count(e); ++i) {
          g.mark_fallback(g.edge_base + en.offset[e] + i);
          bound(g.edge_base + en.offset[e] + i, 0);
        }
      }
      continue;
    }
    // Edge nodes of each local edge (local parameters, ascending), minus lattice coincidences.
    std::array<std::vector<int64_t>, 3> extra_ids;
    std::array<std::map<int, int64_t>, 3> lattice_hits; // local step -> edge node id
    for (int k = 0; k < 3; ++k) {
      const int64_t e = topo.cell_edge(c, k);
      const bool rev = topo.edge_reversed(c, k);
      extra[k].clear();
      const int64_t n = en.count(e);
      for (int64_t i = 0; i < n; ++i) {
        const int64_t gi = rev ? en.offset[e] + n - 1 - i : en.offset[e] + i;
        const double s = rev ? 1 - en.nodes[gi].t : en.nodes[gi].t;
        const double step = std::round(s * K);
        if (std::abs(s * K - step) <= 1e-9 && step > 0 && step < K) {
          lattice_hits[k][static_cast<int>(step)] = g.edge_base + gi;
          continue;
        }
        extra[k].push_back(s);
        extra_ids[k].push_back(g.edge_base + gi);
      }
    }
    Prepared p{c, refine_cell(K, extra), {}, {}};
    const CellRefinement &cr = p.refinement;
    p.ids.resize(cr.vertices.size());
    for (std::size_t i = 0; i < cr.vertices.size(); ++i) {
      const CellSubVertex &sv = cr.vertices[i];
      switch (sv.kind) {
      case CellSubVertex::Kind::Corner:
        p.ids[i] = topo.cell_vertices(c)[sv.corner];
        break;
      case CellSubVertex::Kind::EdgeExtra:
        p.ids[i] = extra_ids[sv.edge][sv.index];
        break;
      case CellSubVertex::Kind::EdgeLattice: {
        auto hit = lattice_hits[sv.edge].find(sv.index);
        if (hit != lattice_hits[sv.edge].end()) {
          p.ids[i] = hit->second;
          break;
        }
        const int64_t e = topo.cell_edge(c, sv.edge);
        const int step = topo.edge_reversed(c, sv.edge) ? K - sv.index : sv.index;
        auto it = lattice_place.try_emplace({e, step}, LatticePlace{c, sv.u, sv.v}).first;
        p.ids[i] = -2 - static_cast<int64_t>(p.lattice.size()); // resolved below
        p.lattice.push_back(&it->second.id);
        break;
      }
      case CellSubVertex::Kind::Interior:
        p.ids[i] = -1;
        break;
      }
    }
    prepared.push_back(std::move(p));
  }
  for (auto &[key, at] : lattice_place)
    lattice_node[key] = at.id =
        g.add_node(field.edge_polynomial(key.first)(static_cast<double>(key.second) / K), at.cell,
                   {at.u, at.v}, NodeLocation::Edge);

  for (Prepared &p : prepared) {
    const int64_t c = p.cell;
    const CellRefinement &cr = p.refinement;
    std::vector<int64_t> &ids = p.ids;
    const BernsteinTriangle poly = field.cell_polynomial(c);
    for (std::size_t i = 0; i < cr.vertices.size(); ++i) {
      const CellSubVertex &sv = cr.vertices[i];
      if (ids[i] == -1) {
        ids[i] = g.add_node(poly(sv.u, sv.v), c, {sv.u, sv.v}, NodeLocation::Interior);
      } else if (ids[i] <= -2) {
        ids[i] = *p.lattice[static_cast<std::size_t>(-2 - ids[i])];
      }
    }
    for (int64_t id : ids)
      if (id >= g.tail_base)
        g.tail_source[id - g.tail_base].fallback = true;
      else
        g.mark_fallback(id);
    // The stand-in's certified distance from the polynomial on this cell.
    double error = 0;
    const InterpolationError interpolation(poly);
    for (const auto &t : cr.triangles) {
      const CellSubVertex &a = cr.vertices[t[0]], &b = cr.vertices[t[1]], &d = cr.vertices[t[2]];
      error = std::max(error, interpolation.on({a.u, a.v}, {b.u, b.v}, {d.u, d.v}));
    }
    out.max_error = std::max(out.max_error, error);
    for (int64_t id : ids)
      bound(id, error);
    for (const auto &t : cr.triangles)
      for (int j = 0; j < 3; ++j) {
        g.common_edges.push_back({ids[t[j]], ids[t[(j + 1) % 3]]});
        if (arc_geometry)
          g.geo_edges.push_back({ids[t[j]], ids[t[(j + 1) % 3]], {}});
      }
  }

  // Certain extrema (strict, from the edge polynomials) are never merged away: they get no
  // slack.
  std::vector<std::pair<int64_t, double>> node_error;
  for (std::size_t id = 0; id < node_bound.size(); ++id)
    if (node_bound[id] >= 0)
      node_error.emplace_back(static_cast<int64_t>(id), node_bound[id]);
  out.node_bound = node_error;
  if (out.max_error > 0) {
    std::vector<uint8_t> wanted(static_cast<std::size_t>(topo.num_vertices()), 0);
    for (const auto &[id, error] : node_error)
      if (id < g.edge_base)
        wanted[id] = 1;
    const std::vector<uint8_t> strict_vertex = strict_vertex_extrema(topo, field, wanted);
    auto certain_extremum = [&](const std::pair<int64_t, double> &entry) {
      const int64_t id = entry.first;
      bool certain = false;
      if (id < g.edge_base) {
        certain = strict_vertex[id] != 0;
      } else if (id < g.tail_base) {
        const int64_t i = id - g.edge_base;
        const int64_t e =
            std::upper_bound(en.offset.begin(), en.offset.end(), i) - en.offset.begin() - 1;
        certain = strict_edge_extremum(topo, field, en, e, i);
      }
      return certain;
    };
    node_error.erase(std::remove_if(node_error.begin(), node_error.end(), certain_extremum),
                     node_error.end());
  }
  out.node_error = std::move(node_error);
  out.lattice_on_edge.reserve(lattice_node.size());
  for (const auto &[key, id] : lattice_node)
    out.lattice_on_edge.emplace_back(key.first, static_cast<double>(key.second) / K, id);
  return out;
}

} // namespace hoct
