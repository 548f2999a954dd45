#include "mesh/field.hpp"

#include "mesh/mesh.hpp"

#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace hoct {
namespace {

// The values and point ids of cell c's nodes along local edge k, from corner k to corner k+1
// (or reversed), into vals[0 .. d] and ids[0 .. d].
void edge_node_values(const MeshInput &in, double reference, int64_t c, int k, bool reversed,
                      double *vals, int64_t *ids) {
  const int d = in.cell_degree[c];
  const int64_t *nodes = &in.cell_nodes[in.cell_offsets[c]];
  for (int t = 0; t <= d; ++t) {
    const int64_t p = nodes[edge_lattice_index(d, k, reversed ? d - t : t)];
    ids[t] = p;
    vals[t] = in.values[p] - reference;
  }
}

// `amplification` units in the last place of the largest |value| (see Field::precision), plus
// 1e-12 of the range. The unit is a double's, or the stored values' own when coarser
// (`value_precision`, the rounding of float32 data: one float32 unit is 2^-23).
double data_precision(double lo, double hi, double amplification, double value_precision) {
  const double magnitude = std::max(std::abs(lo), std::abs(hi));
  const double unit = std::max(std::numeric_limits<double>::epsilon(), 2 * value_precision);
  return amplification * unit * magnitude + 1e-12 * (hi - lo);
}

} // namespace

double reference_value(double lo, double hi) {
  if (!(lo <= hi))
    return 0;
  const double mid = lo + (hi - lo) / 2;
  return std::abs(mid) >= 2 * (hi - lo) ? mid : 0.0;
}

double Field::value_scale() const {
  return std::max({std::abs(min_value_ - reference_), std::abs(max_value_ - reference_),
                   max_value_ - min_value_, 1e-300});
}

BernsteinTriangle Field::cell_polynomial(int64_t c) const {
  auto s = coefficients(c);
  return BernsteinTriangle(degree_[c], std::vector<double>(s.begin(), s.end()));
}

BernsteinPoly Field::edge_polynomial(int64_t e) const {
  const auto s = edge_coefficients(e);
  return BernsteinPoly(std::vector<double>(s.begin(), s.end()));
}

double Field::value(int64_t c, double u, double v) const {
  return reference_ + cell_polynomial(c)(u, v);
}

Field Field::build(const MeshInput &in, const Topology &topo, ProblemLog &problems, int threads,
                   const MeshScales *whole) {
  Field f;
  const int64_t ne = topo.num_edges();
  f.input_degree_.assign(in.cell_degree.begin(), in.cell_degree.end());
  if (whole && !whole->empty()) {
    f.min_value_ = whole->min_value;
    f.max_value_ = whole->max_value;
  } else if (!in.values.empty()) {
    auto [lo, hi] = std::minmax_element(in.values.begin(), in.values.end());
    f.min_value_ = *lo;
    f.max_value_ = *hi;
  }
  f.reference_ = reference_value(f.min_value_, f.max_value_);
  const double ref = f.reference_;
  int max_input_degree = 1;
  for (const uint8_t d : f.input_degree_)
    max_input_degree = std::max(max_input_degree, static_cast<int>(d));
  if (whole)
    max_input_degree = std::max(max_input_degree, whole->max_degree);
  f.precision_ = data_precision(f.min_value_, f.max_value_,
                                std::max(2.0, lagrange_to_bernstein_norm(max_input_degree)),
                                in.value_precision);
  // Continuity is about the input's own values (a solver's rounding of |f|), so its tolerance
  // is relative to their magnitude, and at least a few units of their storage.
  const double scale = std::max({std::abs(f.min_value_), std::abs(f.max_value_), 1e-300});
  const double tol = std::max(kContinuityTolerance, 8 * in.value_precision) * scale;

  // Edge degrees and owners: the lowest-id cell of the highest input degree.
  f.edge_degree_.resize(ne);
  UninitializedVector<int64_t> owner(static_cast<std::size_t>(ne));
  UninitializedVector<int8_t> owner_local(static_cast<std::size_t>(ne));
  const int edge_threads = threads_for(ne, threads, 16384);
  parallel_for(ne, edge_threads, [&](int64_t begin, int64_t end, int) {
    for (int64_t e = begin; e < end; ++e) {
      const int64_t *cells = topo.edge_cells_begin(e);
      int degree = 0;
      int64_t o = -1;
      for (int i = 0; i < topo.edge_cell_count(e); ++i)
        if (in.cell_degree[cells[i]] > degree) {
          degree = in.cell_degree[cells[i]];
          o = cells[i];
        }
      f.edge_degree_[e] = static_cast<uint8_t>(degree);
      owner[e] = o;
      owner_local[e] = static_cast<int8_t>(topo.local_edge(o, e));
    }
  });

  // Edge polynomials, once per edge, from the owner's edge nodes oriented lo -> hi.
  f.edge_offset_.resize(ne + 1);
  parallel_offsets(ne, threads, f.edge_offset_,
                   [&](int64_t e) { return int64_t{f.edge_degree_[e]} + 1; });
  f.edge_coef_->resize(f.edge_offset_[ne]);
  // Fixed blocks of edges, each with its own problem log, appended in block order: the same
  // report on any thread count.
  const int64_t blocks = problem_blocks(ne);
  BlockProblems block_problems(blocks);
  // An edge of linear cells only: its nodes are its two vertices' points in every cell (a
  // vertex is one point), so the cells agree on it by construction, and a degree-1 edge's
  // Bernstein coefficients are its end values, which pin_edge_ends sets.
  auto linear_cells_only = [&](int64_t e) {
    const int64_t *cells = topo.edge_cells_begin(e);
    for (int i = 0; i < topo.edge_cell_count(e); ++i)
      if (in.cell_degree[cells[i]] != 1)
        return false;
    return true;
  };
  parallel_chunks(ne, blocks, edge_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
    ProblemLog &log = block_problems[b];
    // Per edge: no allocation (degrees are at most kMaxDegree).
    double vals[kMaxDegree + 1], other_vals[kMaxDegree + 1];
    int64_t ids[kMaxDegree + 1], other_ids[kMaxDegree + 1];
    for (int64_t e = begin; e < end; ++e) {
      const int64_t c = owner[e];
      const int k = owner_local[e];
      const int d = f.edge_degree_[e];
      if (d == 1 && linear_cells_only(e))
        continue; // its two coefficients are its vertices' values (pin_edge_ends)
      edge_node_values(in, ref, c, k, topo.edge_reversed(c, k), vals, ids);
      double *p = f.edge_coef_->data() + f.edge_offset_[e];
      bernstein_from_equispaced(vals, d, p);

      // Continuity: every other cell of the edge must agree with the owner.
      const int64_t *cells = topo.edge_cells_begin(e);
      for (int i = 0; i < topo.edge_cell_count(e); ++i) {
        const int64_t o = cells[i];
        if (o == c)
          continue;
        const int ko = topo.local_edge(o, e);
        const int od = in.cell_degree[o];
        edge_node_values(in, ref, o, ko, topo.edge_reversed(o, ko), other_vals, other_ids);
        if (od == d && std::equal(other_ids, other_ids + d + 1, ids))
          continue; // the same nodes: continuous by construction
        double gap = 0.0;
        if (od == d) {
          for (int t = 0; t <= d; ++t)
            gap = std::max(gap, std::abs(other_vals[t] - vals[t]));
        } else {
          const BernsteinPoly q = bernstein_from_equispaced(other_vals, od).elevated(d);
          for (int t = 0; t <= d; ++t)
            gap = std::max(gap, std::abs(q[t] - p[t]));
        }
        if (!(gap <= tol)) {
          std::ostringstream m;
          m << "cells " << c << " and " << o << " disagree on their shared edge (points "
            << topo.vertex_point(topo.edge_vertices(e)[0]) << "-"
            << topo.vertex_point(topo.edge_vertices(e)[1]) << ") by " << gap
            << " (the field must be continuous)";
          log.add(Problem::DiscontinuousEdge, m.str());
        }
      }
    }
  });
  block_problems.append_to(problems);

  const int64_t nv = topo.num_vertices();
  f.vertex_value_.resize(nv);
  parallel_for(nv, threads_for(nv, threads, 65536), [&](int64_t begin, int64_t end, int) {
    for (int64_t v = begin; v < end; ++v)
      f.vertex_value_[v] = in.values[topo.vertex_point(v)] - ref;
  });
  f.pin_edge_ends(topo, threads);

  // Cell polynomials from the node values (written in place; raised where an edge has a higher
  // degree), then the shared edges.
  f.assemble_cells(
      topo, f.input_degree_,
      [&](int64_t c, int degree, double *out) {
        const int din = in.cell_degree[c];
        if (din == 1 && degree == 1)
          return; // each of its three coefficients is a corner, copied in from its edges

        const int n = lattice_size(din);
        double stack_vals[91]; // lattice_size(12)
        std::vector<double> heap;
        double *vals = stack_vals;
        if (n > 91) {
          heap.resize(n);
          vals = heap.data();
        }
        for (int i = 0; i < n; ++i)
          vals[i] = in.values[in.cell_nodes[in.cell_offsets[c] + i]] - ref;
        if (din == degree) {
          bernstein_from_lattice_values(vals, din, out);
        } else {
          const BernsteinTriangle p = bernstein_from_lattice_values(vals, din).elevated(degree);
          std::copy(p.coefficients().begin(), p.coefficients().end(), out);
        }
      },
      threads);
  if (whole) // the whole mesh's highest degree (its fallback refinements' size)
    f.max_degree_ = std::max(f.max_degree_, whole->max_degree);
  return f;
}

void Field::assemble_cells(const Topology &topo, std::span<const uint8_t> cell_degree,
                           const std::function<void(int64_t, int, double *)> &cell, int threads) {
  const int64_t nc = topo.num_cells();
  degree_.resize(nc);
  offset_.resize(nc + 1);
  const int cell_threads = threads_for(nc, threads, 32768);
  // Each fixed block's highest degree, combined in block order.
  const int64_t blocks = problem_blocks(nc);
  std::vector<int> block_max(static_cast<std::size_t>(blocks), 0);
  parallel_chunks(nc, blocks, cell_threads, [&](int64_t b, int64_t begin, int64_t end, int) {
    int most = 0;
    for (int64_t c = begin; c < end; ++c) {
      int d = cell_degree[c];
      for (int k = 0; k < 3; ++k)
        d = std::max(d, static_cast<int>(edge_degree_[topo.cell_edge(c, k)]));
      degree_[c] = static_cast<uint8_t>(d);
      most = std::max(most, d);
    }
    block_max[static_cast<std::size_t>(b)] = most;
  });
  max_degree_ = 0;
  for (const int d : block_max)
    max_degree_ = std::max(max_degree_, d);
  parallel_offsets(nc, threads, offset_, [&](int64_t c) { return lattice_size(degree_[c]); });
  auto coef = std::make_shared<UninitializedVector<double>>();
  coef->resize(offset_[nc]);
  parallel_for(nc, threads_for(nc, threads, 4096), [&](int64_t begin, int64_t end, int) {
    for (int64_t c = begin; c < end; ++c) {
      const int d = degree_[c];
      double *out = coef->data() + offset_[c];
      cell(c, d, out);
      for (int k = 0; k < 3; ++k) {
        const int64_t e = topo.cell_edge(c, k);
        const bool rev = topo.edge_reversed(c, k);
        if (edge_degree_[e] == d) {
          const double *p = edge_coef_->data() + edge_offset_[e];
          for (int t = 0; t <= d; ++t)
            out[edge_lattice_index(d, k, t)] = p[rev ? d - t : t];
        } else {
          const BernsteinPoly p = edge_polynomial(e).elevated(d);
          for (int t = 0; t <= d; ++t)
            out[edge_lattice_index(d, k, t)] = p[rev ? d - t : t];
        }
      }
    }
  });
  coef_ = std::move(coef);
}

Field Field::build_from_polynomials(const Topology &topo,
                                    const std::vector<BernsteinTriangle> &cells,
                                    ProblemLog &problems, double value_precision) {
  Field f;
  const int64_t nc = topo.num_cells(), ne = topo.num_edges();
  if (static_cast<int64_t>(cells.size()) != nc)
    throw std::invalid_argument("Field::build_from_polynomials: one polynomial per cell needed");
  f.input_degree_.resize(nc);
  double lo = INFINITY, hi = -INFINITY;
  for (int64_t c = 0; c < nc; ++c) {
    f.input_degree_[c] = static_cast<uint8_t>(cells[c].degree());
    auto [a, b] = cells[c].bounds();
    lo = std::min(lo, a);
    hi = std::max(hi, b);
  }
  // Without node values, the range is the (certified) coefficient enclosure.
  f.min_value_ = nc ? lo : 0.0;
  f.max_value_ = nc ? hi : 0.0;
  // The coefficients are the data: their rounding moves the field by as much.
  f.precision_ = data_precision(f.min_value_, f.max_value_, 2.0, value_precision);
  const double tol = std::max(kContinuityTolerance, 8 * value_precision) *
                     std::max({std::abs(f.min_value_), std::abs(f.max_value_), 1e-300});
  f.edge_degree_.assign(ne, 0);
  f.edge_offset_.assign(ne + 1, 0);
  std::vector<BernsteinPoly> edges(ne);
  for (int64_t e = 0; e < ne; ++e) {
    const int64_t *ec = topo.edge_cells_begin(e);
    int64_t owner = ec[0];
    for (int i = 1; i < topo.edge_cell_count(e); ++i)
      if (cells[ec[i]].degree() > cells[owner].degree())
        owner = ec[i];
    auto restriction = [&](int64_t c) {
      const int k = topo.local_edge(c, e);
      const BernsteinPoly p = cells[c].edge(k);
      return topo.edge_reversed(c, k) ? p.reversed() : p;
    };
    edges[e] = restriction(owner);
    f.edge_degree_[e] = static_cast<uint8_t>(edges[e].degree());
    f.edge_offset_[e + 1] = f.edge_offset_[e] + edges[e].degree() + 1;
    for (int i = 0; i < topo.edge_cell_count(e); ++i) {
      if (ec[i] == owner)
        continue;
      const BernsteinPoly q = restriction(ec[i]).elevated(edges[e].degree());
      double gap = 0.0;
      for (int t = 0; t <= q.degree(); ++t)
        gap = std::max(gap, std::abs(q[t] - edges[e][t]));
      if (!(gap <= tol)) {
        std::ostringstream m;
        m << "cells " << owner << " and " << ec[i] << " disagree on their shared edge (points "
          << topo.vertex_point(topo.edge_vertices(e)[0]) << "-"
          << topo.vertex_point(topo.edge_vertices(e)[1]) << ") by " << gap
          << " (the field must be continuous)";
        problems.add(Problem::DiscontinuousEdge, m.str());
      }
    }
  }
  f.edge_coef_->resize(f.edge_offset_[ne]);
  for (int64_t e = 0; e < ne; ++e)
    std::copy(edges[e].coefficients().begin(), edges[e].coefficients().end(),
              f.edge_coef_->begin() + f.edge_offset_[e]);
  // Vertex values from the lowest-id cell at each vertex; the others must agree.
  f.vertex_value_.assign(topo.num_vertices(), NAN);
  for (int64_t c = 0; c < nc; ++c)
    for (int k = 0; k < 3; ++k) {
      const int64_t v = topo.cell_vertices(c)[k];
      const double val = cells[c].coefficients()[corner_index(cells[c].degree(), k)];
      if (std::isnan(f.vertex_value_[v]))
        f.vertex_value_[v] = val;
      else if (!(std::abs(val - f.vertex_value_[v]) <= tol))
        problems.add(Problem::DiscontinuousVertex,
                     "cell " + std::to_string(c) + " disagrees with a neighbour at point " +
                         std::to_string(topo.vertex_point(v)) + " by " +
                         std::to_string(std::abs(val - f.vertex_value_[v])));
    }
  f.pin_edge_ends(topo, 1);
  f.assemble_cells(
      topo, f.input_degree_,
      [&](int64_t c, int degree, double *out) {
        const BernsteinTriangle p =
            cells[c].degree() == degree ? cells[c] : cells[c].elevated(degree);
        std::copy(p.coefficients().begin(), p.coefficients().end(), out);
      },
      1);
  return f;
}

void Field::pin_edge_ends(const Topology &topo, int threads) {
  const int64_t ne = topo.num_edges();
  parallel_for(ne, threads_for(ne, threads, 65536), [&](int64_t begin, int64_t end, int) {
    for (int64_t e = begin; e < end; ++e) {
      (*edge_coef_)[edge_offset_[e]] = vertex_value_[topo.edge_vertices(e)[0]];
      (*edge_coef_)[edge_offset_[e] + edge_degree_[e]] = vertex_value_[topo.edge_vertices(e)[1]];
    }
  });
}

Field Field::on_cut_topology(const Topology &cut, std::span<const int64_t> edge_origin,
                             std::span<const int64_t> vertex_origin) const {
  // Everything but the edges and vertices, which the cut renumbers (the cells' and edges'
  // coefficients shared, not copied).
  Field f;
  f.degree_ = degree_;
  f.input_degree_ = input_degree_;
  f.offset_ = offset_;
  f.coef_ = coef_;
  f.min_value_ = min_value_;
  f.max_value_ = max_value_;
  f.reference_ = reference_;
  f.precision_ = precision_;
  f.max_degree_ = max_degree_;
  f.edge_coef_ = edge_coef_;
  const int64_t ne = cut.num_edges();
  f.edge_degree_.resize(static_cast<std::size_t>(ne));
  f.edge_offset_.resize(static_cast<std::size_t>(ne) + 1);
  for (int64_t e = 0; e < ne; ++e) {
    f.edge_degree_[e] = edge_degree_[edge_origin[e]];
    f.edge_offset_[e] = edge_offset_[edge_origin[e]];
  }
  f.edge_offset_[ne] = static_cast<int64_t>(f.edge_coef_->size());
  f.vertex_value_.resize(vertex_origin.size());
  for (std::size_t v = 0; v < vertex_origin.size(); ++v)
    f.vertex_value_[v] = vertex_value_[vertex_origin[v]];
  return f;
}

} // namespace hoct
