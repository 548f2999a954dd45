// The piecewise-polynomial scalar field: per cell a triangle Bernstein polynomial on the
// reference triangle, and per global edge ONE univariate Bernstein polynomial (oriented from the
// lower to the higher vertex id) computed once from the shared edge nodes. Every cell's boundary
// coefficients are copies of its edges' polynomials, so the two cells of an edge see bit-identical
// restrictions. Cells sharing an edge with a higher-degree cell are degree-elevated.
#pragma once

#include "mesh/mesh_input.hpp"
#include "mesh/problem_log.hpp"
#include "mesh/topology.hpp"
#include "poly/bernstein_triangle.hpp"
#include "util/uninitialized_vector.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace hoct {

// Values relative to a reference. A field of range 3 around 1e7 (kelvin, pascal) keeps only ~9
// of its doubles' digits for its variation; converted to Bernstein form as it is, every rounding
// and tolerance would scale with 1e7 instead of 3. So the field subtracts a reference value from
// every node value first (exactly: see reference_value) and stores f - reference(): the cell and
// edge coefficients and the vertex values below are all relative to it, and so is everything the
// exact and refined pipelines compute from them. value(), min_value() and max_value() are
// absolute; the pipeline adds reference() back to the values it reports.
//
// The reference for data in [lo, hi]: their midpoint when it lies at least two ranges from zero,
// else 0. Then every x in [lo, hi] lies within [3c/4, 5c/4], so x - c is exact (Sterbenz) and
// (x - c) + c gives x back bit for bit; below that, |x| < 2.5 (hi - lo) already and a shift
// would gain at most a bit or two.
double reference_value(double lo, double hi);

class Field {
public:
  // Relative tolerance (of the value scale) for continuity across edges whose two cells do not
  // share node ids or have different degrees.
  static constexpr double kContinuityTolerance = 1e-9;

  // Builds the field from the Lagrange node values of `input`; records discontinuities across
  // edges in `problems`.
  // `threads`: the per-cell conversion runs in parallel (the result does not depend on it).
  // `whole`: the range and degree of the whole mesh this is a piece of (mesh/mesh.hpp), for its
  // reference, precision and tolerances.
  static Field build(const MeshInput &input, const Topology &topology, ProblemLog &problems,
                     int threads = 1, const struct MeshScales *whole = nullptr);

  // Builds the field from one polynomial per cell (the thesis' general case: e.g. fitted to
  // arbitrary samples with bernstein_from_samples). Each edge's polynomial is taken from the
  // lowest-id cell of highest degree around it; the other cell must agree within
  // kContinuityTolerance (or 8 `value_precision`, the samples' storage rounding: see
  // MeshInput), else a discontinuity is recorded.
  static Field build_from_polynomials(const Topology &topology,
                                      const std::vector<BernsteinTriangle> &cells,
                                      ProblemLog &problems, double value_precision = 0);

  // The same field on `cut`, a copy of its topology with some vertices and edges duplicated
  // (mesh/cut_surface): the same cells and polynomials (their coefficients shared, not copied);
  // edge e of `cut` carries the polynomial of edge edge_origin[e] (in the same orientation),
  // vertex v the value of vertex_origin[v].
  Field on_cut_topology(const Topology &cut, std::span<const int64_t> edge_origin,
                        std::span<const int64_t> vertex_origin) const;

  int64_t num_cells() const { return static_cast<int64_t>(degree_.size()); }
  int degree(int64_t c) const { return degree_[c]; }
  int input_degree(int64_t c) const { return input_degree_[c]; }
  std::span<const double> coefficients(int64_t c) const {
    return {coef_->data() + offset_[c], static_cast<std::size_t>(offset_[c + 1] - offset_[c])};
  }
  BernsteinTriangle cell_polynomial(int64_t c) const;

  int edge_degree(int64_t e) const { return edge_degree_[e]; }
  // The edge's polynomial, parameterised from its lower to its higher vertex.
  BernsteinPoly edge_polynomial(int64_t e) const;
  std::span<const double> edge_coefficients(int64_t e) const {
    return {edge_coef_->data() + edge_offset_[e], static_cast<std::size_t>(edge_degree_[e]) + 1};
  }

  // The field at mesh vertex v minus reference(): the one value every edge and cell uses there
  // (the edge polynomials' end coefficients are set to it exactly).
  double vertex_value(int64_t v) const { return vertex_value_[v]; }

  // The field at (u, v) of cell c: absolute, reference() + the cell polynomial there.
  double value(int64_t c, double u, double v) const;
  // Smallest and largest node value of the input (the data range), absolute.
  double min_value() const { return min_value_; }
  double max_value() const { return max_value_; }
  // The value subtracted from every node value (0 unless the data sit far from zero).
  double reference() const { return reference_; }
  // The smallest persistence the input's values resolve. Each node value is known to half a
  // unit in its last place (at most eps |f|max / 2; float32 data, MeshInput::value_precision:
  // 2^-24 |f|max); that moves the Bernstein coefficients,
  // hence the field, by at most lagrange_to_bernstein_norm(degree) times as much, and a
  // persistence pair by twice that (the stability of persistence diagrams). Plus 1e-12 of the
  // range, the rounding floor of the computation itself (flat-region contraction).
  double precision() const { return precision_; }
  // The largest |node value - reference()|, and at least the range (and 1e-300): the magnitude
  // of the values the computation sees, the scale of its relative tolerances.
  double value_scale() const;
  int max_degree() const { return max_degree_; }

private:
  // Elevates each cell to the highest degree around it and copies its edges' polynomials in.
  // Cell degrees (the largest of the cell's own and its edges'), then every cell's coefficients:
  // cell(c, degree, out) writes cell c's polynomial raised to `degree`; the shared edges are then
  // copied in from the edge polynomials.
  void assemble_cells(const Topology &topology, std::span<const uint8_t> cell_degree,
                      const std::function<void(int64_t, int, double *)> &cell, int threads);
  // Sets each edge polynomial's end coefficients to its vertices' values, bit-exactly.
  void pin_edge_ends(const Topology &topology, int threads);

  // Sized, then filled completely (most by parallel loops: their pages first touched by those).
  UninitializedVector<uint8_t> degree_, input_degree_, edge_degree_;
  UninitializedVector<int64_t> offset_, edge_offset_;
  // Filled completely by parallel loops right after sizing (first touched by their threads). The
  // cells' coefficients, never changed once built, are shared by copies of the field (the field
  // of a surface cut open has the same cells: on_cut_topology).
  std::shared_ptr<UninitializedVector<double>> coef_ =
      std::make_shared<UninitializedVector<double>>();
  // The edges' coefficients, edge e's from edge_offset_[e] (edge_degree_[e] + 1 of them). Shared
  // like the cells': the cut field's copies of an edge point at its original's.
  std::shared_ptr<UninitializedVector<double>> edge_coef_ =
      std::make_shared<UninitializedVector<double>>();
  UninitializedVector<double> vertex_value_;
  double min_value_ = 0, max_value_ = 0, reference_ = 0, precision_ = 0;
  int max_degree_ = 0;
};

} // namespace hoct
