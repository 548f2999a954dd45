// Certified monotone connections inside one cell (docs/ALGORITHM.md §3). From a node c at level
// L = g(c), along a direction into one of its lower sectors: a first segment c -> s certified
// to stay below L (Bernstein coefficients of the segment restriction, skipping the first `skip`
// which are L up to rounding at a critical point), then a straight segment s -> m to a lower node
// m certified below L - margin, or certified descent steps (exact line minimisation along the
// negative gradient, clipped to the triangle) until such a segment exists or the path reaches an
// edge, where the edge's monotonicity between consecutive chain nodes finishes the path.
#pragma once

#include "cell/cell_nodes.hpp"
#include "poly/bernstein_triangle.hpp"

#include <cstdint>

namespace hoct {

struct PathCounters {
  int64_t direct = 0; // straight segment from the sector's start point
  int64_t traced = 0; // needed descent steps
  int64_t failed = 0; // sectors with no certified path: the cell falls back
  int64_t steps = 0;  // descent steps taken in all
};

// The cell's field prepared for path computations (g and its gradient), in one orientation:
// for upper connections pass -g and negated node values.
struct PathField {
  // This field made g, or -g for ascending paths (reusing its storage).
  void assign(const BernsteinTriangle &poly, bool negate);
  BernsteinTriangle g; // its gradient, where descent steps need it, from g.jet()
  double margin = 0;   // certified strict inequalities use level - margin
};

// True if g < threshold on the segment p -> q, ignoring the first `skip` Bernstein coefficients;
// with skip = 0 the segment is subdivided (up to `depth` times) where the hull is too loose.
bool certify_below(const BernsteinTriangle &g, const Vec2 &p, const Vec2 &q, double threshold,
                   int skip, int depth = 6);

// Index into nodes.nodes of a node m with value < level - margin connected to c by a certified
// path below level leaving c along `dir`, or -1. `values` are the node values in the same
// orientation as f.g.
// With `path`, the certified polyline (in the reference triangle) from c to the node is stored.
int connect_lower(const PathField &f, const CellNodes &nodes, const std::vector<double> &values,
                  const Vec2 &c, double level, const Vec2 &dir, int skip, PathCounters &counters,
                  std::vector<Vec2> *path = nullptr);

} // namespace hoct
