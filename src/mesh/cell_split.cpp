#include "mesh/cell_split.hpp"

#include "mesh/field.hpp"
#include "poly/binomial.hpp"
#include "poly/lattice.hpp"
#include "poly/quad_basis.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace hoct {

void CellOrigins::add(int64_t input_cell, Part part) {
  input_cell_.push_back(input_cell);
  part_.push_back(part);
}

void CellOrigins::close(int64_t num_input_cells) {
  first_.assign(static_cast<std::size_t>(num_input_cells) + 1, 0);
  for (const int64_t c : input_cell_)
    ++first_[static_cast<std::size_t>(c) + 1];
  for (std::size_t c = 0; c + 1 < first_.size(); ++c)
    first_[c + 1] += first_[c];
}

CellPlace CellOrigins::to_input(int64_t mesh_cell, std::array<double, 2> uv) const {
  if (identity() || mesh_cell < 0 || mesh_cell >= static_cast<int64_t>(part_.size()))
    return {mesh_cell, uv};
  const double u = uv[0], v = uv[1];
  const int64_t c = input_cell_[static_cast<std::size_t>(mesh_cell)];
  switch (part_[static_cast<std::size_t>(mesh_cell)]) {
  case Diagonal02Low: // corners (0,0) (1,0) (1,1)
    return {c, {u + v, v}};
  case Diagonal02High: // (0,0) (1,1) (0,1)
    return {c, {u, u + v}};
  case Diagonal13Low: // (0,0) (1,0) (0,1)
    return {c, {u, v}};
  case Diagonal13High: // (1,0) (1,1) (0,1)
    return {c, {1 - v, u + v}};
  default:
    return {c, uv};
  }
}

CellPlace CellOrigins::to_mesh(int64_t input_cell, std::array<double, 2> uv) const {
  if (identity())
    return {input_cell, uv};
  if (input_cell < 0 || input_cell >= num_input_cells())
    return {-1, uv};
  const int64_t first = first_[static_cast<std::size_t>(input_cell)];
  const double s = uv[0], t = uv[1];
  switch (part_[static_cast<std::size_t>(first)]) {
  case Diagonal02Low:
    return s >= t ? CellPlace{first, {s - t, t}} : CellPlace{first + 1, {s, t - s}};
  case Diagonal13Low:
    return s + t <= 1 ? CellPlace{first, {s, t}} : CellPlace{first + 1, {s + t - 1, 1 - s}};
  default:
    return {first, uv};
  }
}

namespace {

// B_j(lattice point i) of degree d, row-major: a Bezier triangle's values at its lattice points.
std::vector<double> bernstein_at_lattice(int d) {
  const int n = lattice_size(d);
  std::vector<double> m(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i) {
    const auto p = lattice_point(d, i);
    const long double u = static_cast<long double>(p[0]) / d,
                      v = static_cast<long double>(p[1]) / d;
    for (int j = 0; j < n; ++j) {
      const auto q = lattice_point(d, j);
      const int a = q[0], b = q[1], k = d - a - b;
      long double w = trinomial(k, a, b);
      for (int r = 0; r < k; ++r)
        w *= 1.0L - u - v;
      for (int r = 0; r < a; ++r)
        w *= u;
      for (int r = 0; r < b; ++r)
        w *= v;
      m[static_cast<std::size_t>(i) * n + j] = static_cast<double>(w);
    }
  }
  return m;
}

// A value and a position, interpolated together.
struct Sample {
  double f = 0;
  Vec3 x{0, 0, 0};
  void add(double w, const Sample &o) {
    f += w * o.f;
    for (int a = 0; a < 3; ++a)
      x[a] += w * o.x[a];
  }
};

// The tensor-order corner indices of bidegree p and the local edges (from corner, to corner) in
// tensor direction: edge 0 (0,0)->(1,0), 1 (1,0)->(1,1), 2 (0,1)->(1,1), 3 (0,0)->(0,1).
struct QuadLayout {
  int p;
  int node(int i, int j) const { return i + (p + 1) * j; }
  // The tensor index of the t-th node along edge e (t = 0..p in tensor direction).
  int edge_node(int e, int t) const {
    switch (e) {
    case 0:
      return node(t, 0);
    case 1:
      return node(p, t);
    case 2:
      return node(t, p);
    default:
      return node(0, t);
    }
  }
  // The half-step grid point (k along the edge, 0..2p) of edge e.
  std::array<int, 2> edge_grid(int e, int k) const {
    const int q = 2 * p;
    switch (e) {
    case 0:
      return {k, 0};
    case 1:
      return {q, k};
    case 2:
      return {k, q};
    default:
      return {0, k};
    }
  }
};

// New points per quadrilateral: every half-step grid point that is not one of its nodes
// (Lagrange: the nodes; serendipity: the boundary nodes; Bezier: the corners only).
int64_t new_points(CellKind kind, int p) {
  const int64_t grid = static_cast<int64_t>(2 * p + 1) * (2 * p + 1);
  switch (kind) {
  case CellKind::LagrangeQuadrilateral:
    return grid - static_cast<int64_t>(p + 1) * (p + 1);
  case CellKind::SerendipityQuadrilateral:
    return grid - 4 * p;
  default:
    return grid - 4;
  }
}

class QuadSplitter {
public:
  QuadSplitter(const MeshInput &in, MeshInput &out, double reference)
      : in_(in), out_(out), ref_(reference) {}

  // Writes quadrilateral c's new points from `first_point` on and its two triangles' nodes at
  // `nodes` (2 lattice_size(2p)); returns the diagonal's parts.
  CellOrigins::Part split(int64_t c, int64_t first_point, int64_t *nodes) {
    const CellKind kind = in_.kind(static_cast<std::size_t>(c));
    const int p = in_.cell_degree[static_cast<std::size_t>(c)];
    const int q = 2 * p, g = q + 1;
    const QuadLayout L{p};
    const bool bezier = kind == CellKind::BezierQuadrilateral;
    const std::vector<double> &E = bezier ? bernstein_at_half_steps(p) : lagrange_at_half_steps(p);
    const int64_t *cn = &in_.cell_nodes[static_cast<std::size_t>(in_.cell_offsets[c])];

    // The tensor nodes (their point ids; -1 for a serendipity cell's missing interior) and
    // samples, relative to the reference value.
    const int nt = (p + 1) * (p + 1);
    ids_.assign(static_cast<std::size_t>(nt), -1);
    nodes_.assign(static_cast<std::size_t>(nt), Sample{});
    if (kind == CellKind::SerendipityQuadrilateral) {
      const std::vector<int> boundary = quad_boundary_indices(p);
      for (std::size_t b = 0; b < boundary.size(); ++b)
        ids_[static_cast<std::size_t>(boundary[b])] = cn[b];
    } else {
      for (int i = 0; i < nt; ++i)
        ids_[static_cast<std::size_t>(i)] = cn[i];
    }
    for (int i = 0; i < nt; ++i)
      if (ids_[static_cast<std::size_t>(i)] >= 0)
        nodes_[static_cast<std::size_t>(i)] = sample(ids_[static_cast<std::size_t>(i)]);
    if (kind == CellKind::SerendipityQuadrilateral) {
      const std::vector<double> &S = serendipity_interior(p);
      const std::vector<int> boundary = quad_boundary_indices(p);
      const std::size_t nb = boundary.size();
      int r = 0;
      for (int j = 1; j < p; ++j)
        for (int i = 1; i < p; ++i, ++r) {
          Sample s;
          for (std::size_t b = 0; b < nb; ++b)
            s.add(S[static_cast<std::size_t>(r) * nb + b],
                  nodes_[static_cast<std::size_t>(boundary[b])]);
          nodes_[static_cast<std::size_t>(L.node(i, j))] = s;
        }
    }

    // The half-step grid: rows first (E along s for each node row j), then columns.
    // (Lagrange: the even grid lines are the nodes' own, E's rows there unit vectors: copied.)
    rows_.assign(static_cast<std::size_t>(g * (p + 1)), Sample{});
    for (int j = 0; j <= p; ++j)
      for (int k = 0; k < g; ++k) {
        if (!bezier && k % 2 == 0) {
          rows_[static_cast<std::size_t>(k + g * j)] =
              nodes_[static_cast<std::size_t>(L.node(k / 2, j))];
          continue;
        }
        Sample s;
        for (int i = 0; i <= p; ++i)
          s.add(E[static_cast<std::size_t>(k * (p + 1) + i)],
                nodes_[static_cast<std::size_t>(L.node(i, j))]);
        rows_[static_cast<std::size_t>(k + g * j)] = s;
      }
    grid_.assign(static_cast<std::size_t>(g * g), Sample{});
    grid_id_.assign(static_cast<std::size_t>(g * g), -1);
    for (int l = 0; l < g; ++l)
      for (int k = 0; k < g; ++k) {
        if (!bezier && l % 2 == 0) {
          grid_[static_cast<std::size_t>(k + g * l)] =
              rows_[static_cast<std::size_t>(k + g * (l / 2))];
          continue;
        }
        Sample s;
        for (int j = 0; j <= p; ++j)
          s.add(E[static_cast<std::size_t>(l * (p + 1) + j)],
                rows_[static_cast<std::size_t>(k + g * j)]);
        grid_[static_cast<std::size_t>(k + g * l)] = s;
      }
    // Nodes the cell has keep their points: Lagrange (and serendipity) nodes at even grid
    // points, Bezier corners.
    for (int j = 0; j <= p; ++j)
      for (int i = 0; i <= p; ++i) {
        const int64_t id = ids_[static_cast<std::size_t>(L.node(i, j))];
        const bool corner = (i == 0 || i == p) && (j == 0 || j == p);
        if (id >= 0 && (!bezier || corner))
          grid_id_[static_cast<std::size_t>(2 * i + g * 2 * j)] = id;
      }
    // Edge points from the edge's own nodes, from its lower point id to its higher.
    for (int e = 0; e < 4; ++e) {
      const int64_t a = ids_[static_cast<std::size_t>(L.edge_node(e, 0))],
                    b = ids_[static_cast<std::size_t>(L.edge_node(e, p))];
      const bool forward = a < b;
      for (int k = 1; k < q; ++k) {
        const std::array<int, 2> at = L.edge_grid(e, k);
        const std::size_t gi = static_cast<std::size_t>(at[0] + g * at[1]);
        if (grid_id_[gi] >= 0)
          continue;
        const int kk = forward ? k : q - k;
        Sample s;
        for (int t = 0; t <= p; ++t)
          s.add(E[static_cast<std::size_t>(kk * (p + 1) + t)],
                nodes_[static_cast<std::size_t>(L.edge_node(e, forward ? t : p - t))]);
        grid_[gi] = s;
      }
    }
    // New points for the rest, in grid order.
    int64_t next = first_point;
    for (std::size_t gi = 0; gi < grid_.size(); ++gi)
      if (grid_id_[gi] < 0) {
        grid_id_[gi] = next;
        out_.points[static_cast<std::size_t>(next)] = grid_[gi].x;
        out_.values[static_cast<std::size_t>(next)] = grid_[gi].f + ref_;
        ++next;
      }

    // The diagonal along which the field varies most.
    double lo02 = INFINITY, hi02 = -INFINITY, lo13 = INFINITY, hi13 = -INFINITY;
    for (int k = 0; k < g; ++k) {
      const double a = grid_[static_cast<std::size_t>(k + g * k)].f;
      const double b = grid_[static_cast<std::size_t>((q - k) + g * k)].f;
      lo02 = std::min(lo02, a);
      hi02 = std::max(hi02, a);
      lo13 = std::min(lo13, b);
      hi13 = std::max(hi13, b);
    }
    const bool along02 = !(hi13 - lo13 > hi02 - lo02);
    const int n = lattice_size(q);
    for (int half = 0; half < 2; ++half)
      for (int b = 0; b <= q; ++b)
        for (int a = 0; a + b <= q; ++a) {
          int k, l;
          if (along02) {
            k = half == 0 ? a + b : a;
            l = half == 0 ? b : a + b;
          } else {
            k = half == 0 ? a : q - b;
            l = half == 0 ? b : a + b;
          }
          nodes[half * n + lattice_index(q, a, b)] = grid_id_[static_cast<std::size_t>(k + g * l)];
        }
    return along02 ? CellOrigins::Diagonal02Low : CellOrigins::Diagonal13Low;
  }

private:
  Sample sample(int64_t id) const {
    return {in_.values[static_cast<std::size_t>(id)] - ref_,
            in_.points[static_cast<std::size_t>(id)]};
  }

  const MeshInput &in_;
  MeshInput &out_;
  const double ref_;
  std::vector<int64_t> ids_, grid_id_;
  std::vector<Sample> nodes_, rows_, grid_;
};

// Bezier cells' values and positions at their nodes' positions (lattice points; for a
// quadrilateral, with `quadrilaterals`, its tensor grid), each point once, in cell order, into
// `out` (a copy of in's points and values). A Lagrange cell using one of their non-corner points
// could not agree with them: recorded.
void evaluate_bezier_cells(const MeshInput &in, MeshInput &out, double ref, bool quadrilaterals,
                           ProblemLog &problems) {
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  std::vector<uint8_t> state(in.points.size(), 0); // 1: a Lagrange node, 2: evaluated
  for (int64_t c = 0; c < nc; ++c)
    if (!is_bezier(in.kind(static_cast<std::size_t>(c))))
      for (int64_t i = in.cell_offsets[c]; i < in.cell_offsets[c + 1]; ++i)
        state[static_cast<std::size_t>(in.cell_nodes[static_cast<std::size_t>(i)])] = 1;
  std::vector<double> basis;
  int basis_degree = 0;
  int reported = 0;
  for (int64_t c = 0; c < nc; ++c) {
    const CellKind kind = in.kind(static_cast<std::size_t>(c));
    const bool quad = kind == CellKind::BezierQuadrilateral;
    if (!(kind == CellKind::BezierTriangle || (quad && quadrilaterals)))
      continue;
    const int d = in.cell_degree[static_cast<std::size_t>(c)];
    const int n = cell_node_count(kind, d);
    const int64_t *cn = &in.cell_nodes[static_cast<std::size_t>(in.cell_offsets[c])];
    if (!quad && d != basis_degree) {
      basis = bernstein_at_lattice(d);
      basis_degree = d;
    }
    const std::vector<double> *E = quad ? &bernstein_at_half_steps(d) : nullptr;
    for (int i = 0; i < n; ++i) {
      const std::size_t id = static_cast<std::size_t>(cn[i]);
      const bool corner =
          quad ? (i == 0 || i == d || i == n - 1 || i == d * (d + 1))
               : (i == corner_index(d, 0) || i == corner_index(d, 1) || i == corner_index(d, 2));
      if (corner || state[id] == 2)
        continue;
      if (state[id] == 1) {
        if (reported++ < 5)
          problems.add(Problem::InconsistentNodes,
                       "Bezier cell " + std::to_string(c) + " has point " + std::to_string(id) +
                           " as a control point, which a Lagrange cell uses as a node");
        continue;
      }
      Sample s;
      for (int j = 0; j < n; ++j) {
        const std::size_t pj = static_cast<std::size_t>(cn[j]);
        double w;
        if (quad) // B_a(x_i) B_b(y_i) at the node's (i/d, j/d): rows 2i of the half-step table
          w = (*E)[static_cast<std::size_t>(2 * (i % (d + 1)) * (d + 1) + j % (d + 1))] *
              (*E)[static_cast<std::size_t>(2 * (i / (d + 1)) * (d + 1) + j / (d + 1))];
        else
          w = basis[static_cast<std::size_t>(i) * n + j];
        s.add(w, Sample{in.values[pj] - ref, in.points[pj]});
      }
      out.values[id] = s.f + ref;
      out.points[id] = s.x;
      state[id] = 2;
    }
  }
}

} // namespace

namespace {

double data_reference(const MeshInput &in) {
  double lo = INFINITY, hi = -INFINITY;
  for (const double v : in.values) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return reference_value(lo, hi);
}

MeshInput with_names(const MeshInput &in) {
  MeshInput out;
  out.field_name = in.field_name;
  out.source = in.source;
  out.field_detail = in.field_detail;
  out.warnings = in.warnings;
  out.coordinate_precision = in.coordinate_precision;
  out.value_precision = in.value_precision;
  return out;
}

} // namespace

MeshInput nodal_cells(const MeshInput &in, ProblemLog &problems) {
  MeshInput out = with_names(in);
  const double ref = data_reference(in);
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  out.points.assign(in.points.begin(), in.points.end());
  out.values.assign(in.values.begin(), in.values.end());
  evaluate_bezier_cells(in, out, ref, /*quadrilaterals=*/true, problems);
  std::vector<int64_t> nodes;
  for (int64_t c = 0; c < nc; ++c) {
    const CellKind kind = in.kind(static_cast<std::size_t>(c));
    const int d = in.cell_degree[static_cast<std::size_t>(c)];
    const int64_t *cn = &in.cell_nodes[static_cast<std::size_t>(in.cell_offsets[c])];
    const int64_t *ce = &in.cell_nodes[static_cast<std::size_t>(in.cell_offsets[c + 1])];
    if (kind != CellKind::SerendipityQuadrilateral) {
      nodes.assign(cn, ce);
      out.add_cell(is_quadrilateral(kind) ? CellKind::LagrangeQuadrilateral
                                          : CellKind::LagrangeTriangle,
                   d, nodes.data());
      continue;
    }
    // The interior nodes a serendipity cell lacks: new points, from its interpolant.
    const std::vector<int> boundary = quad_boundary_indices(d);
    const std::vector<double> &S = serendipity_interior(d);
    nodes.assign(static_cast<std::size_t>((d + 1) * (d + 1)), -1);
    for (std::size_t b = 0; b < boundary.size(); ++b)
      nodes[static_cast<std::size_t>(boundary[b])] = cn[b];
    int r = 0;
    for (int j = 1; j < d; ++j)
      for (int i = 1; i < d; ++i, ++r) {
        Sample s;
        for (std::size_t b = 0; b < boundary.size(); ++b)
          s.add(S[static_cast<std::size_t>(r) * boundary.size() + b],
                Sample{in.values[static_cast<std::size_t>(cn[b])] - ref,
                       in.points[static_cast<std::size_t>(cn[b])]});
        nodes[static_cast<std::size_t>(i + (d + 1) * j)] = static_cast<int64_t>(out.points.size());
        out.points.push_back(s.x);
        out.values.push_back(s.f + ref);
      }
    out.add_cell(CellKind::LagrangeQuadrilateral, d, nodes.data());
  }
  return out;
}

SplitCells split_cells(const MeshInput &in, ProblemLog &problems, int threads) {
  SplitCells r;
  r.mesh = with_names(in);
  MeshInput &out = r.mesh;
  const int64_t nc = static_cast<int64_t>(in.num_cells());
  const double ref = data_reference(in);

  // Sizes: each cell's new points, triangles and nodes.
  std::vector<int64_t> point_start(static_cast<std::size_t>(nc) + 1, 0);
  std::vector<int64_t> cell_start(static_cast<std::size_t>(nc) + 1, 0);
  out.cell_offsets.assign(1, 0);
  for (int64_t c = 0; c < nc; ++c) {
    const CellKind kind = in.kind(static_cast<std::size_t>(c));
    const int d = in.cell_degree[static_cast<std::size_t>(c)];
    int64_t added = 0, cells = 1;
    if (is_quadrilateral(kind)) {
      added = new_points(kind, d);
      cells = 2;
      ++r.quadrilaterals;
    }
    r.bezier_cells += is_bezier(kind);
    point_start[static_cast<std::size_t>(c) + 1] = point_start[static_cast<std::size_t>(c)] + added;
    cell_start[static_cast<std::size_t>(c) + 1] = cell_start[static_cast<std::size_t>(c)] + cells;
    const int degree = is_quadrilateral(kind) ? 2 * d : d;
    for (int64_t t = 0; t < cells; ++t) {
      out.cell_offsets.push_back(out.cell_offsets.back() + lattice_size(degree));
      out.cell_degree.push_back(static_cast<uint8_t>(degree));
    }
  }
  const std::size_t np = in.points.size();
  out.points.resize(np + static_cast<std::size_t>(point_start.back()));
  out.values.resize(np + static_cast<std::size_t>(point_start.back()));
  std::copy(in.points.begin(), in.points.end(), out.points.begin());
  std::copy(in.values.begin(), in.values.end(), out.values.begin());
  out.cell_nodes.resize(static_cast<std::size_t>(out.cell_offsets.back()));
  std::vector<uint8_t> parts(static_cast<std::size_t>(cell_start.back()), CellOrigins::Whole);

  // Triangles copied, quadrilaterals split, in parallel blocks (each cell writes its own slots).
  parallel_for(nc, threads_for(nc, threads, 4096), [&](int64_t begin, int64_t end, int) {
    QuadSplitter splitter(in, out, ref);
    for (int64_t c = begin; c < end; ++c) {
      const CellKind kind = in.kind(static_cast<std::size_t>(c));
      const int64_t t = cell_start[static_cast<std::size_t>(c)];
      int64_t *nodes =
          &out.cell_nodes[static_cast<std::size_t>(out.cell_offsets[static_cast<std::size_t>(t)])];
      if (is_quadrilateral(kind)) {
        const CellOrigins::Part part = splitter.split(
            c, static_cast<int64_t>(np) + point_start[static_cast<std::size_t>(c)], nodes);
        parts[static_cast<std::size_t>(t)] = part;
        parts[static_cast<std::size_t>(t) + 1] = part + 1;
      } else {
        std::copy(&in.cell_nodes[static_cast<std::size_t>(in.cell_offsets[c])],
                  &in.cell_nodes[static_cast<std::size_t>(in.cell_offsets[c + 1])], nodes);
      }
    }
  });
  for (int64_t c = 0; c < nc; ++c)
    for (int64_t t = cell_start[static_cast<std::size_t>(c)];
         t < cell_start[static_cast<std::size_t>(c) + 1]; ++t)
      r.origins.add(c, static_cast<CellOrigins::Part>(parts[static_cast<std::size_t>(t)]));
  r.origins.close(nc);

  if (r.bezier_cells > 0)
    evaluate_bezier_cells(in, out, ref, /*quadrilaterals=*/false, problems);
  return r;
}

} // namespace hoct
