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

#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

class Field {
public:
  // Relative tolerance (of the value scale) for continuity across edges whose two cells do not
  // share node ids or have different degrees.
  static constexpr double kContinuityTolerance = 1e-9;

  // Builds the field; records discontinuities across edges in `problems`.
  static Field build(const MeshInput &input, const Topology &topology, ProblemLog &problems);

  int64_t num_cells() const { return static_cast<int64_t>(degree_.size()); }
  int degree(int64_t c) const { return degree_[c]; }
  int input_degree(int64_t c) const { return input_degree_[c]; }
  std::span<const double> coefficients(int64_t c) const {
    return {coef_.data() + offset_[c], static_cast<std::size_t>(offset_[c + 1] - offset_[c])};
  }
  BernsteinTriangle cell_polynomial(int64_t c) const;

  int edge_degree(int64_t e) const { return edge_degree_[e]; }
  // The edge's polynomial, parameterised from its lower to its higher vertex.
  BernsteinPoly edge_polynomial(int64_t e) const;

  double value(int64_t c, double u, double v) const;
  // Smallest and largest node value of the input (the data range).
  double min_value() const { return min_value_; }
  double max_value() const { return max_value_; }
  int max_degree() const { return max_degree_; }

private:
  std::vector<uint8_t> degree_, input_degree_, edge_degree_;
  std::vector<int64_t> offset_, edge_offset_;
  std::vector<double> coef_, edge_coef_;
  double min_value_ = 0, max_value_ = 0;
  int max_degree_ = 0;
};

} // namespace hoct
