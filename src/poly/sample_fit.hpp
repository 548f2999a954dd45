// The thesis' general input: a cell's polynomial given by values at arbitrary sample positions in
// the reference triangle. Solves the Bernstein-Vandermonde system; an ill-conditioned sample set
// (samples on or near a curve of degree d, coincident samples) is rejected with a clear error.
#pragma once

#include "poly/bernstein_triangle.hpp"

#include <vector>

namespace hoct {

struct SampleFitOptions {
  // Reject when the condition number of the (column-scaled) system exceeds this.
  double max_condition = 1e10;
  // With more samples than coefficients (least squares), reject when the residual exceeds this
  // fraction of the value range: the samples do not come from a degree-d polynomial.
  double max_relative_residual = 1e-8;
};

// positions: (u, v) per sample; values: one per sample; at least lattice_size(degree) samples.
// Throws hoct::Error describing the problem (count, conditioning, residual).
BernsteinTriangle bernstein_from_samples(const std::vector<Vec2> &positions,
                                         const std::vector<double> &values, int degree,
                                         const SampleFitOptions &options = {});

} // namespace hoct
